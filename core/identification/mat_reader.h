// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/identification/experiment_table.h"

#include <cstddef>
#include <string>
#include <vector>

namespace xyt {

/// One variable of a MAT file as listed (its data not read).
struct MatVariableInfo {
    std::string name;
    std::size_t rows = 0, columns = 0; ///< of a rank-2 variable (0, 0 for other ranks)
    std::string className;             ///< "double", "single", "int16", ..., "char", "struct", ...
    bool usable = false;               ///< a real numeric vector (1 x n or n x 1, n >= 1), not logical
    std::string whyNot;                ///< when not usable: "is complex", "is a 3 x 4 matrix", ...
};

struct MatFileInfo {
    std::string version; ///< "v4", "v5" (MATLAB 5 to 7.2, -v7 included) or "v7.3" (HDF5)
    std::vector<MatVariableInfo> variables;
};

/**
 * Lists the variables of a MATLAB .mat file (libmatio: v4, v5/v7 with or without compression,
 * v7.3 through HDF5). The file must be a regular file of at most kMaxExperimentBytes bytes; a
 * v5/v7.3 file must start with the 128-byte MATLAB header ("MATLAB 5.0 MAT-file" text, version
 * 0x0100 or 0x0200, endian indicator "IM" or "MI"), a v4 file a chain of valid v4 matrix
 * headers whose data ends exactly at the end of the file; in a v5 file every top-level element
 * must be a matrix (or a compressed one, its head inflated) that fits in the file, with an array
 * header whose dimensions and name it can hold. libmatio allocates what a file claims, so these
 * checks (ours, before libmatio opens the file) keep junk from asking for gigabytes; v7.3 files
 * are HDF5, checked only by libhdf5 (and by the element bound of readMat).
 * @throws FileError naming @p path when it cannot be read (no such file, not a regular file,
 *         too large); InvalidInput naming it when it is not a MAT file libmatio can open.
 */
MatFileInfo listMatVariables(const std::string& path);

/**
 * Reads the real numeric vectors @p names (every usable one when empty) of a MAT file into a
 * table whose rows are the vectors' elements (rowLabel "element", rowNumbers 1..n; columns may
 * differ in length). Integer and single classes are converted to double exactly. A variable
 * claiming more elements than 1032 x the file size (deflate's largest ratio) is refused before
 * libmatio reads it. A NaN or an
 * infinity is kept as a problem of its column (refused when that column is used).
 * @throws FileError as listMatVariables; InvalidInput naming the file: a name that is not in the
 *         file (with the list of usable ones), a variable that is not a real numeric vector
 *         (saying what it is), more than kMaxExperimentColumns variables.
 */
ExperimentTable readMat(const std::string& path, const std::vector<std::string>& names = {});

} // namespace xyt
