# SPDX-License-Identifier: GPL-3.0-or-later
# Fails unless every translatable string of the current sources has a translation in the
# committed catalogue. Runs lupdate over the sources into a copy of the catalogue (the committed
# file is never written), then reads the copy: a message lupdate added (a new or changed source
# string) is type="unfinished"; one whose source is gone is type="vanished" or "obsolete"; an
# empty <translation> or an empty plural form is untranslated. Arguments:
#   -DLUPDATE=<lupdate> -DTS=<committed .ts> -DWORK=<scratch dir> -DINCLUDE=<repo root>
#   -DSOURCES_FILE=<file listing the translated sources, one a line>
#   -DALIASES=<lupdate -tr-function-alias value: the core's marks, core/CMakeLists.txt>
foreach(var LUPDATE TS WORK INCLUDE SOURCES_FILE ALIASES)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "check_translations_complete.cmake: -D${var}=... is required")
    endif()
endforeach()
if(NOT EXISTS "${TS}")
    message(FATAL_ERROR "${TS}: no such catalogue")
endif()
get_filename_component(ts_name "${TS}" NAME)
file(MAKE_DIRECTORY "${WORK}")
set(copy "${WORK}/${ts_name}")
file(COPY_FILE "${TS}" "${copy}")
file(READ "${TS}" committed)
execute_process(
    COMMAND "${LUPDATE}" -locations none -tr-function-alias "${ALIASES}" -I "${INCLUDE}"
            "@${SOURCES_FILE}" -ts "${copy}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "lupdate failed (${rc}):\n${out}\n${err}")
endif()
file(READ "${copy}" updated)
string(REGEX MATCHALL "<translation type=\"(unfinished|vanished|obsolete)\"" flagged "${updated}")
string(REGEX MATCHALL "<translation>[ \t\r\n]*</translation>|<translation/>|<numerusform>[ \t\r\n]*</numerusform>|<numerusform/>"
       empty "${updated}")
list(LENGTH flagged n_flagged)
list(LENGTH empty n_empty)
string(REGEX MATCHALL "<message[ >]" messages "${updated}")
list(LENGTH messages n_messages)
if(n_messages LESS 1)
    message(FATAL_ERROR "${ts_name}: lupdate found no message at all: the sources list is wrong")
endif()
if(n_flagged GREATER 0 OR n_empty GREATER 0)
    # Name the offending sources so the translator knows what to do (';' would split the
    # list of matches: entities such as &amp; are shown without it).
    string(REPLACE ";" "" updated "${updated}")
    string(REGEX MATCHALL "<source>[^<]*</source>[^<]*(<oldsource>[^<]*</oldsource>[^<]*)?(<comment>[^<]*</comment>[^<]*)?<translation type=\"(unfinished|vanished|obsolete)\""
           which "${updated}")
    set(listing "")
    foreach(m IN LISTS which)
        string(REGEX REPLACE "^<source>([^<]*)</source>.*type=\"([a-z]+)\"$" "  [\\2] \\1" line
                             "${m}")
        string(APPEND listing "${line}\n")
    endforeach()
    message(FATAL_ERROR
        "${ts_name}: ${n_flagged} message(s) unfinished or gone from the sources and ${n_empty} "
        "empty translation(s), of ${n_messages}. Refresh the catalogue (ninja update_translations), "
        "translate, and check with translations/tools/check_ts.py.\n${listing}")
endif()
message(STATUS "${ts_name}: all ${n_messages} messages translated")
