# Installation (docs/embedding.md "Installing"): the libraries, their public headers, the CMake package
# (find_package(tomc CONFIG REQUIRED COMPONENTS core diagnostics dds c)), tomc.pc for pkg-config, the IEC 61131-3
# declarations, and a Debian package through CPack. Every installed path is relative to the prefix, so an
# installed tree can be moved (tests/install/install_test.sh moves it before using it).
include(CMakePackageConfigHelpers)

# tomc::core: the core library (telegrams, drives, technology objects, MC_* instructions), standard library and
# Threads only (ARCHITECTURE-GUIDE §1).
add_library(tomc_core INTERFACE)
add_library(tomc::core ALIAS tomc_core)
target_link_libraries(tomc_core INTERFACE tomc::instructions)

set_target_properties(tomc_telegrams PROPERTIES EXPORT_NAME telegrams)
set_target_properties(tomc_drives PROPERTIES EXPORT_NAME drives)
set_target_properties(tomc_techobjects PROPERTIES EXPORT_NAME techobjects)
set_target_properties(tomc_instructions PROPERTIES EXPORT_NAME instructions)
set_target_properties(tomc_core PROPERTIES EXPORT_NAME core)
set_target_properties(tomc_diagnostics PROPERTIES EXPORT_NAME diagnostics)

set(TOMC_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/tomc)

install(TARGETS tomc_telegrams tomc_drives tomc_techobjects tomc_instructions tomc_core
        EXPORT tomcCoreTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS tomc_diagnostics
        EXPORT tomcDiagnosticsTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development)
# tomc::dds: the Fast DDS gateway adapter and the contract's generated types (docs/gateway.md).
set_target_properties(tomc_drives_dds PROPERTIES EXPORT_NAME dds)
set_target_properties(tomc_gateway_types PROPERTIES EXPORT_NAME gateway_types)
install(TARGETS tomc_drives_dds tomc_gateway_types
        EXPORT tomcDdsTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/drives/dds/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT development)
install(FILES ${PROJECT_BINARY_DIR}/generated/idl/tomc_gateway.h ${PROJECT_BINARY_DIR}/generated/idl/tomc_gatewayPubSubTypes.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tomc/idl COMPONENT development)
install(TARGETS tomc_c
        EXPORT tomcCTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT development)
foreach(part Core Diagnostics Dds C)
  install(EXPORT tomc${part}Targets NAMESPACE tomc:: DESTINATION ${TOMC_CMAKE_DIR} COMPONENT development)
endforeach()

# Public headers (the headers of the libraries above; not those of the tools or of the web server).
foreach(dir telegrams drives techobjects instructions)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          COMPONENT development)
endforeach()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/diagnostics/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT development
        PATTERN "server.hpp" EXCLUDE PATTERN "api.hpp" EXCLUDE PATTERN "trace_image.hpp" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/capi/include/tomc/tomc.h ${PROJECT_SOURCE_DIR}/capi/include/tomc/tomc_instructions.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tomc COMPONENT development)
install(FILES ${PROJECT_SOURCE_DIR}/capi/iec/tomc_motion.st DESTINATION ${CMAKE_INSTALL_DATADIR}/tomc/iec
        COMPONENT development)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/tomcConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/tomcConfig.cmake INSTALL_DESTINATION ${TOMC_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/tomcConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/tomcConfig.cmake ${PROJECT_BINARY_DIR}/tomcConfigVersion.cmake
        DESTINATION ${TOMC_CMAKE_DIR} COMPONENT development)

# pkg-config: the C library (prefix from the .pc file's own location, so the tree stays relocatable).
file(RELATIVE_PATH TOMC_PC_TO_PREFIX "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
configure_file(${PROJECT_SOURCE_DIR}/cmake/tomc.pc.in ${PROJECT_BINARY_DIR}/tomc.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/tomc.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT development)

# Debian package: `cpack -G DEB` in the build directory (library, headers, CMake package, CLI).
set(CPACK_PACKAGE_NAME tomc)
set(CPACK_PACKAGE_VENDOR "tomc")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "S7-1500 Motion Control model: technology objects, MC_* instructions, PROFIdrive")
set(CPACK_PACKAGE_CONTACT "tomc maintainers")
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
include(CPack)
