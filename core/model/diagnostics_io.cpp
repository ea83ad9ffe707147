// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_tables.h"

namespace xyt::diagnostic_tables {

/// The refusals of core/io (file_io.cpp) and of the readers that open files themselves: why a
/// file could not be read or written (FileError's reason). The system's own messages (strerror)
/// are not ours: they stay uncoded.
const std::vector<DiagnosticTemplate>& io() {
    static const std::vector<DiagnosticTemplate> table = {
        XYT_DIAGNOSTIC("io_no_such_file", "no such file"),
        XYT_DIAGNOSTIC("io_is_directory", "is a directory"),
        XYT_DIAGNOSTIC("io_directory_not_session", "is a directory, not a session file"),
        XYT_DIAGNOSTIC("io_not_regular_file", "is not a regular file"),
        XYT_DIAGNOSTIC("io_not_regular_to_read",
                       "is not a regular file (a device, FIFO or socket); refusing to read it"),
        XYT_DIAGNOSTIC("io_not_regular_to_replace",
                       "is not a regular file (a device, FIFO or socket); refusing to replace it"),
        XYT_DIAGNOSTIC("io_larger_than_limit", "is larger than the limit of %1 bytes"),
        XYT_DIAGNOSTIC("io_size_over_limit", "%1 bytes is larger than the limit of %2 bytes"),
        XYT_DIAGNOSTIC("io_empty_file_name", "the file name is empty"),
        XYT_DIAGNOSTIC("io_foreign_link_to_nothing",
                       "is a symbolic link of another user (%1) to a file that does not exist; "
                       "refusing to create it"),
        XYT_DIAGNOSTIC("io_link_to_foreign_file",
                       "is a symbolic link to a file of another user (the file: %1, the link: "
                       "%2); refusing to replace it"),
        XYT_DIAGNOSTIC("io_foreign_file_in_sticky",
                       "is a file of another user (%1) in a folder everyone may write to "
                       "(sticky); refusing to replace it"),
        XYT_DIAGNOSTIC("io_foreign_link_in_sticky",
                       "is a symbolic link of another user (%1) in a folder everyone may write to "
                       "(sticky); refusing to follow it"),
    };
    return table;
}

} // namespace xyt::diagnostic_tables
