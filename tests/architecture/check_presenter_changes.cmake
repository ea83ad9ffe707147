# SPDX-License-Identifier: GPL-3.0-or-later
# Presenters own every change (README.md, Architecture): no view or panel (ui/ outside
# ui/session/) replaces the session itself with TuningSession::apply; it calls the presenter's
# setter, which makes the change one named undo step.
#   cmake -DROOT=<tree> -P check_presenter_changes.cmake
if(NOT ROOT)
    message(FATAL_ERROR "usage: cmake -DROOT=<source tree> -P check_presenter_changes.cmake")
endif()
file(GLOB_RECURSE sources RELATIVE "${ROOT}" "${ROOT}/ui/*.cpp" "${ROOT}/ui/*.h")
set(violations 0)
foreach(file IN LISTS sources)
    if(file MATCHES "^ui/session/")
        continue()
    endif()
    file(STRINGS "${ROOT}/${file}" lines)
    set(number 0)
    foreach(line IN LISTS lines)
        math(EXPR number "${number} + 1")
        if(line MATCHES "(->|\\.)apply\\(")
            message(SEND_ERROR "${file}:${number}: calls apply() on the session: use a TuningSession setter")
            math(EXPR violations "${violations} + 1")
        endif()
    endforeach()
endforeach()
if(violations GREATER 0)
    message(FATAL_ERROR "${violations} view change(s) bypass the presenter's setters")
endif()
message(STATUS "presenter changes: no view in ${ROOT}/ui calls apply()")
