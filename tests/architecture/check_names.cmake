# SPDX-License-Identifier: GPL-3.0-or-later
# Names come from the domain, not from the project's history (README.md, "References"):
#   cmake -DROOT=<tree> -P check_names.cmake
# Fails naming each file and line that cites a tracker entry by its number, or one of the two
# papers by a numbered alias instead of its authors. CHANGELOG.md, where history belongs, build
# trees and the fixtures of tests/architecture are left out.
cmake_minimum_required(VERSION 3.25)
if(NOT ROOT)
    message(FATAL_ERROR "usage: cmake -DROOT=<source tree> -P check_names.cmake")
endif()

# Both patterns are matched on lower-cased text, so identifiers in camelCase are caught too. They
# are assembled from pieces so that this file does not match them itself.
set(word_issue "issue")
set(word_paper "paper")
set(tracker_pattern "(^|[^a-z])${word_issue}s?[ _#-]*(no\\.? ?)?[0-9]")
set(alias_pattern "(^|[^a-z])${word_paper}[ _#-]*00[01]([^0-9]|$)")

set(extensions cpp h c txt cmake md sh py m json nc csv tsv lvm yml yaml)
set(globs "")
foreach(folder IN ITEMS app core ui tests scripts resources docs .ci)
    foreach(ext IN LISTS extensions)
        list(APPEND globs "${ROOT}/${folder}/*.${ext}")
    endforeach()
endforeach()
file(GLOB_RECURSE files RELATIVE "${ROOT}" ${globs})
file(GLOB top RELATIVE "${ROOT}" "${ROOT}/*.md" "${ROOT}/*.txt" "${ROOT}/*.cmake")
list(APPEND files ${top})
list(REMOVE_DUPLICATES files)
list(SORT files)

set(violations 0)
set(scanned 0)
foreach(file IN LISTS files)
    if(file STREQUAL "CHANGELOG.md" OR file MATCHES "^tests/architecture/fixture_"
       OR file MATCHES "(^|/)build[^/]*/")
        continue()
    endif()
    math(EXPR scanned "${scanned} + 1")
    file(READ "${ROOT}/${file}" text)
    string(TOLOWER "${text}" text)
    # Most files cite nothing: one look at the whole text, line breaks and comment leaders
    # folded, decides whether the lines need reading.
    string(REGEX REPLACE "\n[ \t]*(//+|/?\\*+|#+|%+|;+|\"|-)?[ \t]*" " " folded "${text}")
    if(NOT folded MATCHES "${tracker_pattern}" AND NOT folded MATCHES "${alias_pattern}")
        continue()
    endif()
    # One list element per line, empty lines kept so that the numbers are the file's own; the
    # characters that would change how CMake splits a list are replaced first.
    foreach(special IN ITEMS "[" "]" "\\" "\r")
        string(REPLACE "${special}" "_" text "${text}")
    endforeach()
    string(REPLACE ";" "_" text "${text}")
    string(REPLACE "\n" ";" lines "${text}")
    set(number 0)
    set(tail "")
    foreach(line IN LISTS lines)
        math(EXPR number "${number} + 1")
        set(lower "${line}")
        # A reference split over two lines: the end of the previous one joined to the start of
        # this one without its comment leader.
        string(REGEX REPLACE "^ [ \t]*(//+|/?\\*+|#+|%+|;+|\"|-)?[ \t]*" "" head " ${lower}")
        set(joined "${tail} ${head}")
        set(what "")
        if(lower MATCHES "${tracker_pattern}")
            set(what "names a tracker entry by number; name the feature instead")
        elseif(lower MATCHES "${alias_pattern}")
            set(what "cites a paper by a numbered alias; cite its authors (README.md, References)")
        elseif(joined MATCHES "${tracker_pattern}")
            set(what "names a tracker entry by number across the line break; name the feature instead")
        elseif(joined MATCHES "${alias_pattern}")
            set(what "cites a paper by a numbered alias across the line break; cite its authors")
        endif()
        if(what)
            message(SEND_ERROR "${file}:${number}: ${what}")
            math(EXPR violations "${violations} + 1")
            set(tail "") # reported once, not again with the next line
            continue()
        endif()
        string(LENGTH "${lower}" length)
        if(length GREATER 24)
            math(EXPR start "${length} - 24")
            string(SUBSTRING "${lower}" ${start} 24 tail)
        else()
            set(tail "${lower}")
        endif()
    endforeach()
endforeach()
if(violations GREATER 0)
    message(FATAL_ERROR "${violations} line(s) cite history or a paper alias")
endif()
message(STATUS "names: ${scanned} files in ${ROOT} name features and authors, not numbers")
