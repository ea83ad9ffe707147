# SPDX-License-Identifier: GPL-3.0-or-later
# The man pages format without a warning and document what the programs say they take:
#   cmake -DMAN_DIR=<docs/man> -DCLI=<xytune-cli> -DGUI=<xytune> -P check_man_pages.cmake
#  - `groff -man -ww -z -Tutf8` (all warnings) prints nothing for xytune.1 and xytune-cli.1;
#  - every command that `xytune-cli --help` lists is a tag of xytune-cli.1 (`.B name` or
#    `\fBname`), and every long option that `xytune --help` lists is in xytune.1.
cmake_minimum_required(VERSION 3.25)
find_program(groff_path groff)
if(NOT groff_path)
    message(FATAL_ERROR "groff not found: install the Debian package groff-base")
endif()
foreach(page xytune.1 xytune-cli.1)
    execute_process(COMMAND ${groff_path} -man -ww -z -Tutf8 "${MAN_DIR}/${page}"
                    OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0 OR NOT "${out}${err}" STREQUAL "")
        message(FATAL_ERROR "groff -man -ww on ${page}: exit ${rc}\n${out}${err}")
    endif()
endforeach()

# The commands: the lines of the general usage indented by two spaces, a name first.
execute_process(COMMAND "${CLI}" --help OUTPUT_VARIABLE usage RESULT_VARIABLE rc)
string(REGEX MATCHALL "\n  [a-z]+[ \n]" commands "${usage}")
list(TRANSFORM commands STRIP)
list(REMOVE_DUPLICATES commands)
list(LENGTH commands command_count)
if(NOT rc EQUAL 0 OR command_count LESS 10)
    message(FATAL_ERROR "xytune-cli --help: exit ${rc}, ${command_count} commands found:\n${usage}")
endif()
file(READ "${MAN_DIR}/xytune-cli.1" cli_page)
foreach(command IN LISTS commands)
    if(NOT cli_page MATCHES "\n(\\.B |\\\\fB)${command}[ \n\\\\]")
        message(FATAL_ERROR "xytune-cli.1 has no entry for the command '${command}'")
    endif()
endforeach()

execute_process(COMMAND "${GUI}" --help OUTPUT_VARIABLE usage RESULT_VARIABLE rc)
string(REGEX MATCHALL "--[a-z][a-z-]*" options "${usage}")
list(REMOVE_DUPLICATES options)
list(LENGTH options count)
if(NOT rc EQUAL 0 OR count LESS 4)
    message(FATAL_ERROR "xytune --help: exit ${rc}, ${count} options found:\n${usage}")
endif()
file(READ "${MAN_DIR}/xytune.1" gui_page)
foreach(option IN LISTS options)
    string(REPLACE "-" "\\\\-" escaped "${option}") # roff writes a hyphen-minus as \-
    if(NOT gui_page MATCHES "${escaped}([^a-z\\\\-]|\\\\[^-])")
        message(FATAL_ERROR "xytune.1 does not document ${option}")
    endif()
endforeach()
message(STATUS "man pages: ${count} options of xytune, ${command_count} commands of xytune-cli (${commands})")
