// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/identification/experiment_table.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace xyt {

/// One variable of a MAT file as listed (its data not read).
struct MatVariableInfo {
    std::string name;
    std::size_t rows = 0, columns = 0; ///< of a rank-2 variable (0, 0 for other ranks)
    std::string className;             ///< "double", "single", "int16", ..., "char", "struct", ...
    std::uint64_t elements = 0;        ///< the product of all its dimensions (what it claims)
    bool usable = false; ///< a real numeric vector (1 x n or n x 1, n >= 1), not logical
    Diagnostic whyNot;   ///< when not usable: "is complex", "is a cell array", ... (coded)
};

/// The most elements one MAT variable may hold to be read: 2^24 (16 777 216, 128 MiB as
/// doubles; 46 hours sampled at 10 ms). libmatio allocates a variable's data whole, then the
/// reader converts it to double, so one variable costs up to 16 bytes an element while it is
/// read; the bound is on that memory, never on the file's size (an unwritten HDF5 dataset or a
/// compressed run of zeros claims gigabytes from a few kilobytes).
inline constexpr std::uint64_t kMaxMatVariableElements = std::uint64_t(1) << 24;
/// The most elements the variables of one read may hold together: 2^26 (512 MiB as doubles),
/// as many numbers as the largest text file (kMaxExperimentBytes, a digit and a separator a
/// number) can hold, so a MAT file never needs more memory than a text file may.
inline constexpr std::uint64_t kMaxMatTableElements = std::uint64_t(1) << 26;

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
 * are HDF5, checked only by libhdf5. Only headers are read here, never a variable's data.
 * @throws FileError naming @p path when it cannot be read (no such file, not a regular file,
 *         too large); InvalidInput naming it when it is not a MAT file libmatio can open.
 */
MatFileInfo listMatVariables(const std::string& path);

/**
 * Reads the real numeric vectors @p names of a MAT file into a table whose rows are the
 * vectors' elements (rowLabel "element", rowNumbers 1..n; columns may differ in length). Only
 * the variables named are read: the others are listed by their headers (libmatio reads a
 * header without its data) and never read. Integer and single classes are converted to double
 * exactly. A NaN or an infinity is kept as a problem of its column (refused when that column is
 * used).
 *
 * With @p names empty (a caller that shows the file's variables to choose from), every usable
 * vector is read in the order listed (file order; HDF5 lists v7.3 variables by name), except those
 * beyond kMaxMatVariableElements, beyond kMaxExperimentColumns or beyond kMaxMatTableElements in
 * total: these are left out, each with a line in the table's warnings naming it and why.
 * @throws FileError as listMatVariables; InvalidInput naming the file, before any data is read:
 *         more than kMaxExperimentColumns names, a name given twice, a name that is not in the
 *         file (with the list of usable ones), a variable that is not a real numeric vector
 *         (saying what it is: a cell array, a struct, text, complex, sparse, logical, a
 *         matrix, more than two dimensions, empty), a variable of more than
 *         kMaxMatVariableElements elements, variables of more than kMaxMatTableElements
 *         elements together; after: a variable whose data libmatio cannot read.
 */
ExperimentTable readMat(const std::string& path, const std::vector<std::string>& names = {});

} // namespace xyt
