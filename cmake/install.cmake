# Installation and the Debian package (`cpack -G DEB` in the build folder).
#
# The package installs with the prefix /usr: the programs in /usr/bin (the unit starts
# /usr/bin/gemkiosk), the default catalogue in /usr/share/gemkiosk/catalogue (where the kiosk
# looks for it, kiosk/catalogue/catalogue.hpp). Paths the rest of the system fixes are
# absolute: the config in /etc/gemkiosk (kiosk/settings/kiosk_config.hpp), the units where
# systemd looks for them. `cmake --install` with another prefix moves only the first group.
include(GNUInstallDirs)

# Where systemd wants its files, from its pkg-config file when there is one (Debian 12:
# /lib/systemd/system, /usr/lib/sysusers.d, /usr/lib/tmpfiles.d), else Debian's defaults.
pkg_get_variable(GEM_PKG_UNIT_DIR systemd systemdsystemunitdir)
pkg_get_variable(GEM_PKG_SYSUSERS_DIR systemd sysusersdir)
pkg_get_variable(GEM_PKG_TMPFILES_DIR systemd tmpfilesdir)
if(NOT GEM_PKG_UNIT_DIR)
  set(GEM_PKG_UNIT_DIR /lib/systemd/system)
endif()
if(NOT GEM_PKG_SYSUSERS_DIR)
  set(GEM_PKG_SYSUSERS_DIR /usr/lib/sysusers.d)
endif()
if(NOT GEM_PKG_TMPFILES_DIR)
  set(GEM_PKG_TMPFILES_DIR /usr/lib/tmpfiles.d)
endif()
set(GEM_SYSTEMD_UNIT_DIR ${GEM_PKG_UNIT_DIR} CACHE PATH "systemd system unit folder")
set(GEM_SYSUSERS_DIR ${GEM_PKG_SYSUSERS_DIR} CACHE PATH "sysusers.d folder")
set(GEM_TMPFILES_DIR ${GEM_PKG_TMPFILES_DIR} CACHE PATH "tmpfiles.d folder")
set(GEM_CONFIG_DIR /etc/gemkiosk CACHE PATH "folder of gemkiosk.toml")

# Programs: those this build has (gemkiosk exists once the kiosk app does).
foreach(program gemkiosk gemtables gemrender)
  if(TARGET ${program})
    install(TARGETS ${program} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endforeach()

if(EXISTS ${PROJECT_SOURCE_DIR}/config/gemkiosk.toml)
  install(FILES ${PROJECT_SOURCE_DIR}/config/gemkiosk.toml DESTINATION ${GEM_CONFIG_DIR})
endif()
# The default catalogue, once the default_catalogue target has built it.
install(DIRECTORY ${CMAKE_BINARY_DIR}/catalogue/
        DESTINATION ${CMAKE_INSTALL_DATADIR}/gemkiosk/catalogue OPTIONAL)

install(FILES ${PROJECT_SOURCE_DIR}/systemd/gemkiosk.service
              ${PROJECT_SOURCE_DIR}/systemd/gemkiosk-catalogue.path
              ${PROJECT_SOURCE_DIR}/systemd/gemkiosk-catalogue.service
        DESTINATION ${GEM_SYSTEMD_UNIT_DIR})
install(FILES ${PROJECT_SOURCE_DIR}/systemd/sysusers.d/gemkiosk.conf DESTINATION ${GEM_SYSUSERS_DIR})
install(FILES ${PROJECT_SOURCE_DIR}/systemd/tmpfiles.d/gemkiosk.conf DESTINATION ${GEM_TMPFILES_DIR})
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The Debian package.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME gemkiosk)
set(CPACK_PACKAGE_VENDOR "gemkiosk")
set(CPACK_PACKAGE_CONTACT "gemkiosk maintainers <gemkiosk@example.org>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "store display of faceted gemstones with real refraction")
# CPack puts CPACK_PACKAGE_DESCRIPTION_SUMMARY on the first line, this below it.
string(CONCAT CPACK_DEBIAN_PACKAGE_DESCRIPTION
       "gemkiosk shows faceted gemstones, loose or set in rings, fullscreen on a DRM/KMS\n"
       "display without a desktop, turned with a finger on a touchscreen. It starts at boot\n"
       "as the systemd service gemkiosk.service. Includes gemtables (ray-table databases)\n"
       "and gemrender.")
# Absolute destinations (/etc, the systemd folders) go into the package's tree, not onto this
# machine: CPack installs with DESTDIR and the prefix CPACK_INSTALL_PREFIX.
set(CPACK_SET_DESTDIR ON)
set(CPACK_INSTALL_PREFIX /usr)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# The package carries the programs without their debugging information.
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION misc)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://example.org/gemkiosk")
# The maintainer scripts call systemd-sysusers, systemd-tmpfiles and deb-systemd-helper.
# Mesa's EGL and DRI drivers (llvmpipe when there is no GPU) are loaded at run time, so
# shlibdeps cannot see them.
# polkitd: libseat's logind backend asks logind to activate the kiosk's session, and logind
# lets a user other than root do that only with polkit's consent (the action
# org.freedesktop.login1.chvt, granted to a user in an active local session by systemd's own
# policy); without polkitd the kiosk gets no devices ("Could not activate session: Permission
# denied"), found by the VM test (tests/vm).
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "systemd, init-system-helpers, libegl-mesa0, libgl1-mesa-dri, polkitd")
find_program(GEM_DPKG_SHLIBDEPS dpkg-shlibdeps)
if(GEM_DPKG_SHLIBDEPS)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
endif()
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA
    ${PROJECT_SOURCE_DIR}/packaging/conffiles ${PROJECT_SOURCE_DIR}/packaging/postinst
    ${PROJECT_SOURCE_DIR}/packaging/prerm ${PROJECT_SOURCE_DIR}/packaging/postrm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)
