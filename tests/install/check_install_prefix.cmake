# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the build into a fresh temporary prefix and runs what was installed from there:
#   cmake -DBUILD=<build dir> -DSOURCE=<source dir> -DBUILT_GUI=<build-tree xytune>
#         -DBINDIR=bin -DLIBDIR=lib -DDATADIR=share -DMANDIR=share/man -DAPP_ID=<id>
#         -P check_install_prefix.cmake
# Checks (GNUInstallDirs' layout, cmake/Install.cmake):
#  - every installed file lies in one of the folders the layout names, and each expected file
#    is there (programs, private libraries, desktop entry, icon, metainfo, man pages, examples
#    with every G-code program of resources/examples);
#  - the installed programs load their libraries from the prefix (ldd), with no
#    LD_LIBRARY_PATH: `xytune-cli report` prints Braga et al.'s lower-base PI, and
#    `xytune --screenshot` writes a PNG;
#  - the installed workbench finds <prefix>/share/xytune/examples, while the build-tree one
#    finds the source tree's resources/examples (so the comparison can fail).
# The programs run with HOME and the XDG folders inside the prefix: nothing is written
# outside the temporary folder (but the build folder's install_manifest.txt, which
# `cmake --install` always writes).
cmake_minimum_required(VERSION 3.25)
foreach(var BUILD SOURCE BUILT_GUI BINDIR LIBDIR DATADIR MANDIR APP_ID)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "check_install_prefix.cmake: -D${var}=... is missing")
    endif()
endforeach()

execute_process(COMMAND mktemp -d -t xytune-install.XXXXXX OUTPUT_VARIABLE tmp
                OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT IS_DIRECTORY "${tmp}")
    message(FATAL_ERROR "mktemp -d failed (${rc})")
endif()
file(REAL_PATH "${tmp}" tmp)
set(prefix "${tmp}/prefix")

# Fails after removing the temporary folder (XYT_KEEP_INSTALL=1 keeps it to look into).
function(fail text)
    if("$ENV{XYT_KEEP_INSTALL}" STREQUAL "")
        file(REMOVE_RECURSE "${tmp}")
    else()
        message(STATUS "kept ${tmp}")
    endif()
    message(FATAL_ERROR "${text}")
endfunction()

execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD}" --prefix "${prefix}"
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    fail("cmake --install ${BUILD} --prefix ${prefix} failed (${rc}):\n${out}\n${err}")
endif()

# The layout.
set(expected_files
    "${BINDIR}/xytune" "${BINDIR}/xytune-cli"
    "${LIBDIR}/xytune/libxyt_core.so" "${LIBDIR}/xytune/libxyt_files.so"
    "${LIBDIR}/xytune/libxyt_ui.so"
    "${DATADIR}/applications/${APP_ID}.desktop"
    "${DATADIR}/icons/hicolor/scalable/apps/${APP_ID}.svg"
    "${DATADIR}/metainfo/${APP_ID}.metainfo.xml"
    "${MANDIR}/man1/xytune.1.gz" "${MANDIR}/man1/xytune-cli.1.gz"
    "${DATADIR}/doc/xytune/copyright" "${DATADIR}/doc/xytune/changelog.gz")
foreach(f IN LISTS expected_files)
    if(NOT EXISTS "${prefix}/${f}")
        fail("not installed: ${prefix}/${f}")
    endif()
endforeach()
foreach(program xytune xytune-cli)
    execute_process(COMMAND test -x "${prefix}/${BINDIR}/${program}" RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
        fail("${prefix}/${BINDIR}/${program} is not executable")
    endif()
endforeach()
file(GLOB source_programs RELATIVE "${SOURCE}/resources/examples" "${SOURCE}/resources/examples/*.nc")
list(LENGTH source_programs source_count)
if(source_count EQUAL 0)
    fail("no G-code program in ${SOURCE}/resources/examples")
endif()
foreach(f IN LISTS source_programs)
    if(NOT EXISTS "${prefix}/${DATADIR}/xytune/examples/${f}")
        fail("example ${f} not installed in ${prefix}/${DATADIR}/xytune/examples")
    endif()
endforeach()
set(allowed_folders "${BINDIR}" "${LIBDIR}/xytune" "${DATADIR}/applications"
    "${DATADIR}/icons/hicolor/scalable/apps" "${DATADIR}/metainfo" "${MANDIR}/man1"
    "${DATADIR}/xytune/examples" "${DATADIR}/doc/xytune")
file(GLOB_RECURSE installed RELATIVE "${prefix}" "${prefix}/*")
foreach(f IN LISTS installed)
    get_filename_component(folder "${f}" DIRECTORY)
    if(NOT folder IN_LIST allowed_folders)
        fail("installed outside the layout: ${f} (allowed folders: ${allowed_folders})")
    endif()
    get_filename_component(name "${f}" NAME)
    if(name MATCHES "^tst_|bench")
        fail("a test or the benchmark was installed: ${f}")
    endif()
endforeach()

# The programs, with no library path from the caller and the user's folders in the prefix.
set(run ${CMAKE_COMMAND} -E env --unset=LD_LIBRARY_PATH "HOME=${tmp}/home"
    "XDG_CONFIG_HOME=${tmp}/home/.config" "XDG_DATA_HOME=${tmp}/home/.local/share"
    "XDG_CACHE_HOME=${tmp}/home/.cache" "XDG_RUNTIME_DIR=${tmp}/runtime")
file(MAKE_DIRECTORY "${tmp}/home" "${tmp}/runtime")
file(CHMOD "${tmp}/runtime" DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)

foreach(program xytune xytune-cli)
    execute_process(COMMAND ${run} ldd "${prefix}/${BINDIR}/${program}"
                    OUTPUT_VARIABLE ldd RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0 OR ldd MATCHES "not found")
        fail("ldd ${program}: (${rc})\n${ldd}")
    endif()
    string(REGEX MATCHALL "libxyt_[a-z]+\\.so => [^ ]+" resolved "${ldd}")
    if(resolved STREQUAL "")
        fail("ldd ${program} lists no project library:\n${ldd}")
    endif()
    foreach(line IN LISTS resolved)
        string(REGEX REPLACE ".* => " "" path "${line}")
        file(REAL_PATH "${path}" path) # ldd prints the RUNPATH's $ORIGIN/../ unresolved
        if(NOT path MATCHES "^${prefix}/${LIBDIR}/xytune/libxyt_[a-z]+\\.so$")
            fail("${program} loads a project library from outside the prefix: ${line}")
        endif()
    endforeach()
endforeach()

# Braga et al. Eq. 20 for the lower base: ki = kp psi1 = 16/77.8 = 0.2056555..., printed with
# six significant digits in the PI's transfer function.
execute_process(COMMAND ${run} "${prefix}/${BINDIR}/xytune-cli" report
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT out MATCHES "G_c\\(s\\) += 30 \\+ 0\\.205656/s")
    fail("installed xytune-cli report: exit ${rc}, no 'G_c(s) = 30 + 0.205656/s':\n${out}\n${err}")
endif()

set(shot "${tmp}/shot.png")
execute_process(COMMAND ${run} QT_QPA_PLATFORM=offscreen "${prefix}/${BINDIR}/xytune"
                        --screenshot "${shot}" --size 800x600
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 120)
if(NOT rc EQUAL 0 OR NOT EXISTS "${shot}")
    fail("installed xytune --screenshot: exit ${rc}, ${shot} missing:\n${out}\n${err}")
endif()
file(SIZE "${shot}" size)
file(READ "${shot}" magic LIMIT 8 HEX)
if(size EQUAL 0 OR NOT magic STREQUAL "89504e470d0a1a0a") # the PNG signature (RFC 2083)
    fail("${shot}: ${size} bytes, signature ${magic}: not a PNG")
endif()

# The examples the installed workbench offers are its own; the build tree's are the source's.
file(REAL_PATH "${prefix}/${DATADIR}/xytune/examples" installed_examples)
file(REAL_PATH "${SOURCE}/resources/examples" source_examples)
execute_process(COMMAND ${run} "${prefix}/${BINDIR}/xytune" --print-examples-folder
                OUTPUT_VARIABLE out OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT out STREQUAL installed_examples)
    fail("installed xytune --print-examples-folder: exit ${rc}, '${out}', expected '${installed_examples}'")
endif()
execute_process(COMMAND ${run} "${BUILT_GUI}" --print-examples-folder
                OUTPUT_VARIABLE out OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT out STREQUAL source_examples)
    fail("build-tree xytune --print-examples-folder: exit ${rc}, '${out}', expected '${source_examples}'")
endif()

file(REMOVE_RECURSE "${tmp}")
message(STATUS "installed into a temporary prefix: ${source_count} example programs, both programs run")
