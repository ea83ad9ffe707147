# SPDX-License-Identifier: GPL-3.0-or-later
# Runs a validator and fails on a non-zero exit or on any line of its output that starts with
# one of the prefixes it uses for errors and warnings:
#   cmake "-DCOMMAND=appstreamcli;validate;--no-net;FILE" "-DFAIL_LINES=^[EW]: "
#         -DPACKAGE=appstream -P check_validator.cmake
# (PACKAGE: the Debian package that provides the tool, named when the tool is missing;
# scripts/dev.sh installs it.)
cmake_minimum_required(VERSION 3.25)
list(GET COMMAND 0 tool)
find_program(tool_path ${tool})
if(NOT tool_path)
    message(FATAL_ERROR "${tool} not found: install the Debian package ${PACKAGE}")
endif()
execute_process(COMMAND ${COMMAND} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
set(text "${out}${err}")
message("${text}")
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${COMMAND}: exit ${rc}")
endif()
string(REPLACE ";" "," text "${text}")
string(REPLACE "\n" ";" lines "${text}")
foreach(line IN LISTS lines)
    if(line MATCHES "${FAIL_LINES}")
        message(FATAL_ERROR "${tool} reports: ${line}")
    endif()
endforeach()
