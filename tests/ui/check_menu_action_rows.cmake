# SPDX-License-Identifier: GPL-3.0-or-later
# tst_menu_actions runs in parts, one CTest run per session state (tests/ui/CMakeLists.txt).
# This check lists the test's own rows (-datatags) and fails when one belongs to a state that
# no part runs, or when a listed state has no rows, so a state added to the test is never
# silently skipped.   cmake -DEXE=<tst_menu_actions> -DSTATES="a;b" -P check_menu_action_rows.cmake
cmake_minimum_required(VERSION 3.20)
execute_process(COMMAND ${EXE} -datatags OUTPUT_VARIABLE out RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${EXE} -datatags failed (${rc})")
endif()
string(REPLACE "\n" ";" lines "${out}")
set(found)
foreach(line IN LISTS lines)
    if(line MATCHES "^TstMenuActions everyActionInEveryState ([^,]+), (saved|modified), dialogs (accepted|rejected)$")
        list(APPEND found "${CMAKE_MATCH_1}")
        if(NOT "${CMAKE_MATCH_1}" IN_LIST STATES)
            message(FATAL_ERROR "state '${CMAKE_MATCH_1}' of tst_menu_actions has no CTest run: add it to xyt_menu_states")
        endif()
    elseif(line MATCHES "everyActionInEveryState")
        message(FATAL_ERROR "row not in the 'state, saved|modified, dialogs accepted|rejected' form: ${line}")
    endif()
endforeach()
foreach(state IN LISTS STATES)
    if(NOT "${state}" IN_LIST found)
        message(FATAL_ERROR "xyt_menu_states lists '${state}', which tst_menu_actions does not have")
    endif()
endforeach()
list(LENGTH found n)
message(STATUS "${n} rows, every state run")
