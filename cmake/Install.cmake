# SPDX-License-Identifier: GPL-3.0-or-later
# What `cmake --install` and `cpack -G DEB` put where (GNUInstallDirs, included at the top):
#   bin/                         xytune, xytune-cli
#   lib/xytune/ (LIBDIR)         the project's shared libraries, private to the programs
#   share/xytune/examples/       the example programs, logs and sessions (ui/session/install_paths.h)
#   share/applications/, share/icons/hicolor/scalable/apps/, share/metainfo/: desktop integration
#   share/man/man1/              xytune.1.gz, xytune-cli.1.gz
#   share/doc/xytune/            copyright (Debian's format), changelog.gz (the package's Debian changelog)
# Tests and the benchmark program are not installed. docs/install.md describes the result.

# The libraries are no public API: they go to a folder of their own, which the executables
# find through their RUNPATH relative to themselves (and each library its siblings through
# $ORIGIN), so an installed tree runs at any prefix or DESTDIR without LD_LIBRARY_PATH.
set(XYT_INSTALL_PRIVATE_LIBDIR "${CMAKE_INSTALL_LIBDIR}/xytune")
file(RELATIVE_PATH xyt_bin_to_private_libs "${CMAKE_INSTALL_FULL_BINDIR}"
     "${CMAKE_INSTALL_PREFIX}/${XYT_INSTALL_PRIVATE_LIBDIR}")
set(xyt_installed_libraries xyt_core xyt_files xyt_ui)
set(xyt_installed_programs xytune xytune-cli)
set_target_properties(${xyt_installed_programs} PROPERTIES
                      INSTALL_RPATH "$ORIGIN/${xyt_bin_to_private_libs}")
set_target_properties(${xyt_installed_libraries} PROPERTIES INSTALL_RPATH "$ORIGIN")

install(TARGETS ${xyt_installed_programs} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${xyt_installed_libraries} LIBRARY DESTINATION ${XYT_INSTALL_PRIVATE_LIBDIR})

# The examples folder by kind of file, so that what is added there later is installed too.
install(DIRECTORY resources/examples/ DESTINATION ${CMAKE_INSTALL_DATADIR}/xytune/examples
        USE_SOURCE_PERMISSIONS
        FILES_MATCHING PATTERN "*.nc" PATTERN "*.json" PATTERN "*.csv" PATTERN "*.lvm"
                       PATTERN "*.md" PATTERN "*.sh")

set(XYT_APP_ID io.github.xytune.XYTune)
install(FILES resources/desktop/${XYT_APP_ID}.desktop
        DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES resources/desktop/${XYT_APP_ID}.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
install(FILES resources/desktop/${XYT_APP_ID}.metainfo.xml
        DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
# The man pages and the change log compressed as Debian's policy asks (gzip -9n: no name or
# time stamp, so the package is reproducible), the copyright file in Debian's machine-readable
# format; `lintian` finds no error in the package (tests/install's deb_package).
file(STRINGS resources/debian/changelog xyt_deb_changelog_head LIMIT_COUNT 1)
if(NOT xyt_deb_changelog_head MATCHES "^xytune \\(${PROJECT_VERSION}\\) ")
    message(FATAL_ERROR "resources/debian/changelog's first entry is not version "
                        "${PROJECT_VERSION} (the project's): ${xyt_deb_changelog_head}")
endif()
set(xyt_gzipped "")
foreach(pair "docs/man/xytune.1|man/xytune.1.gz" "docs/man/xytune-cli.1|man/xytune-cli.1.gz"
        "resources/debian/changelog|doc/changelog.gz")
    string(REPLACE "|" ";" pair "${pair}")
    list(GET pair 0 source)
    list(GET pair 1 target)
    get_filename_component(target_dir "${PROJECT_BINARY_DIR}/${target}" DIRECTORY)
    add_custom_command(OUTPUT ${PROJECT_BINARY_DIR}/${target}
        COMMAND ${CMAKE_COMMAND} -E make_directory ${target_dir}
        COMMAND gzip -9nc ${PROJECT_SOURCE_DIR}/${source} > ${PROJECT_BINARY_DIR}/${target}
        DEPENDS ${PROJECT_SOURCE_DIR}/${source} VERBATIM)
    list(APPEND xyt_gzipped ${PROJECT_BINARY_DIR}/${target})
endforeach()
add_custom_target(xyt_install_documents ALL DEPENDS ${xyt_gzipped})
install(FILES ${PROJECT_BINARY_DIR}/man/xytune.1.gz ${PROJECT_BINARY_DIR}/man/xytune-cli.1.gz
        DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${PROJECT_BINARY_DIR}/doc/changelog.gz resources/debian/copyright
        DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/xytune)

# The Debian package: `cpack -G DEB` in the build folder, after a complete build.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME xytune)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "XY Tune developers")
set(CPACK_PACKAGE_CONTACT "XY Tune developers <xytune@users.noreply.github.io>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # xytune_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# The extended description (CPack puts CPACK_PACKAGE_DESCRIPTION_SUMMARY before it as the
# synopsis line and indents each line by one space).
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "XY Tune designs, simulates and compares position controllers for the axes of an
XY coordinate table: Guillemin-Truxal PI, pole placement with ZPETC feedforward
and LinuxCNC's PID with command feedforward, with root locus, Bode, Nyquist,
step and contour views, system identification from logged experiments, input
shaping and robustness studies. The package holds the workbench (xytune), the
command-line tool (xytune-cli), example G-code programs and logs.")
# Depends from dpkg-shlibdeps over the staged binaries and libraries. It finds the private
# libraries in the package itself through the RUNPATH ($ORIGIN resolved), so no
# CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS into the build tree is needed (tests/install's
# deb_package checks that Depends names no project library).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
include(CPack)
