# SPDX-License-Identifier: GPL-3.0-or-later
# Makes the Debian package of the build in a temporary folder and reads it back:
#   cmake -DBUILD=<build dir> -DVERSION=<project version> -DAPP_ID=<id> -DCPACK=<cpack>
#         -P check_deb_package.cmake
# Checks: the control fields (name, version, section), Depends as dpkg-shlibdeps wrote them
# (Qt Widgets, QCustomPlot, matio and the C library, nothing of the build tree: the private
# libraries are in the package), the package's files under /usr, and lintian's findings.
cmake_minimum_required(VERSION 3.25)
foreach(var BUILD VERSION APP_ID CPACK)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "check_deb_package.cmake: -D${var}=... is missing")
    endif()
endforeach()
execute_process(COMMAND mktemp -d -t xytune-deb.XXXXXX OUTPUT_VARIABLE tmp
                OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT IS_DIRECTORY "${tmp}")
    message(FATAL_ERROR "mktemp -d failed (${rc})")
endif()
function(fail text)
    if("$ENV{XYT_KEEP_INSTALL}" STREQUAL "")
        file(REMOVE_RECURSE "${tmp}")
    else()
        message(STATUS "kept ${tmp}")
    endif()
    message(FATAL_ERROR "${text}")
endfunction()

execute_process(COMMAND ${CPACK} -G DEB --config "${BUILD}/CPackConfig.cmake" -B "${tmp}"
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
file(GLOB debs "${tmp}/xytune_*.deb")
list(LENGTH debs count)
if(NOT rc EQUAL 0 OR NOT count EQUAL 1)
    fail("cpack -G DEB: exit ${rc}, ${count} package(s):\n${out}\n${err}")
endif()

function(field name expected_regex)
    execute_process(COMMAND dpkg-deb -f "${debs}" ${name} OUTPUT_VARIABLE value
                    OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0 OR NOT value MATCHES "${expected_regex}")
        fail("${debs}: ${name} is '${value}', expected to match '${expected_regex}'")
    endif()
endfunction()
field(Package "^xytune$")
field(Version "^${VERSION}$")
field(Section "^science$")
# The libraries the programs link, by their Debian 12 package names (dpkg-shlibdeps).
foreach(dependency libqt6widgets6 libqt6core6 libqcustomplot2.1-qt6 libmatio11 libc6 libstdc\\+\\+6)
    field(Depends "(^|, )${dependency}( |,|$)")
endforeach()
execute_process(COMMAND dpkg-deb -f "${debs}" Depends OUTPUT_VARIABLE depends)
if(depends MATCHES "xyt")
    fail("Depends names a project library (dpkg-shlibdeps did not find it in the package): ${depends}")
endif()

execute_process(COMMAND dpkg-deb -c "${debs}" OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
foreach(path usr/bin/xytune usr/bin/xytune-cli usr/lib/xytune/libxyt_ui.so
        usr/share/applications/${APP_ID}.desktop usr/share/metainfo/${APP_ID}.metainfo.xml
        usr/share/icons/hicolor/scalable/apps/${APP_ID}.svg usr/share/man/man1/xytune-cli.1.gz
        usr/share/man/man1/xytune.1.gz usr/share/doc/xytune/copyright
        usr/share/doc/xytune/changelog.gz)
    string(REPLACE "." "\\." path_regex "${path}")
    string(REPLACE "+" "\\+" path_regex "${path_regex}")
    if(NOT listing MATCHES " \\./${path_regex}\n")
        fail("${debs} does not hold /${path}:\n${listing}")
    endif()
endforeach()
if(NOT listing MATCHES " \\./usr/share/xytune/examples/[^/\n]+\\.nc\n")
    fail("${debs} holds no example program:\n${listing}")
endif()
if(listing MATCHES "tst_|xytune-bench")
    fail("${debs} holds a test or the benchmark:\n${listing}")
endif()
# Debian's package checker: no error. Its one warning, maintscript-calls-ldconfig, comes from
# CPack, which calls ldconfig for any library under /usr/lib (here the private ones in
# /usr/lib/xytune, which need no ldconfig but whose call does no harm).
find_program(LINTIAN lintian)
if(NOT LINTIAN)
    fail("lintian is not installed (Debian package lintian; scripts/dev.sh installs it)")
endif()
execute_process(COMMAND ${LINTIAN} --tag-display-limit 0 "${debs}"
                OUTPUT_VARIABLE lintian_out ERROR_VARIABLE lintian_err)
string(REGEX MATCHALL "(^|\n)[EW]: [^\n]*" lintian_findings "${lintian_out}")
list(FILTER lintian_findings EXCLUDE REGEX "maintscript-calls-ldconfig")
if(lintian_findings)
    fail("lintian on ${debs}:\n${lintian_out}${lintian_err}")
endif()
get_filename_component(name "${debs}" NAME)
file(REMOVE_RECURSE "${tmp}")
message(STATUS "${name}: Depends: ${depends}")
