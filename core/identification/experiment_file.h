// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/identification/experiment_table.h"

#include <cstddef>
#include <string>
#include <vector>

namespace xyt {

/// The kinds of experiment file XY Tune reads.
enum class ExperimentFileKind { Delimited, Lvm, Mat };

/// By the file name's extension, case-insensitive: .lvm, .mat, anything else delimited text
/// (.csv, .tsv, .txt, ...).
ExperimentFileKind experimentFileKind(const std::string& path);

/**
 * Reads any experiment file into its table of named columns: CSV/TSV (delimiter and decimal
 * separator detected), LabVIEW .lvm (segment @p lvmSegment, 1-based) or MATLAB .mat. The
 * table names the file as @p path is written. With @p columns given, a text file keeps only
 * those, checked before its rows are read, and a MAT file reads only those variables, never
 * one nobody asked for; empty: every column, or every usable vector within the bounds of
 * readMat (mat_reader.h).
 * @throws FileError when the file cannot be read; InvalidInput from the reader (file, line,
 *         column).
 */
ExperimentTable readExperimentTable(const std::string& path, std::size_t lvmSegment = 1,
                                    const std::vector<std::string>& columns = {});

} // namespace xyt
