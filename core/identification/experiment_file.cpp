// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/experiment_file.h"

#include "core/identification/delimited_reader.h"
#include "core/identification/lvm_reader.h"
#include "core/identification/mat_reader.h"

#include <algorithm>
#include <cctype>

namespace xyt {

ExperimentFileKind experimentFileKind(const std::string& path) {
    std::string lower = path;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const auto endsWith = [&](const std::string& suffix) {
        return lower.size() >= suffix.size() &&
               lower.compare(lower.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    if (endsWith(".lvm"))
        return ExperimentFileKind::Lvm;
    if (endsWith(".mat"))
        return ExperimentFileKind::Mat;
    return ExperimentFileKind::Delimited;
}

ExperimentTable readExperimentTable(const std::string& path, std::size_t lvmSegment,
                                    const std::vector<std::string>& columns) {
    switch (experimentFileKind(path)) {
    case ExperimentFileKind::Lvm: {
        LvmReadOptions o;
        o.segment = lvmSegment;
        o.columns = columns;
        return readLvmFile(path, o).table;
    }
    case ExperimentFileKind::Mat:
        return readMat(path, columns);
    case ExperimentFileKind::Delimited:
        break;
    }
    DelimitedReadOptions o;
    o.columns = columns;
    return readDelimitedFile(path, o).table;
}

} // namespace xyt
