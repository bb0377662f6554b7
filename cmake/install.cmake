# `cmake --install`: the program, the library with its headers, a CMake
# package (find_package(zeroset) → the target zeroset::zeroset) and a
# pkg-config file. docs/library.md says which headers are the API.
include(CMakePackageConfigHelpers)

install(TARGETS zeroset_app RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS zeroset EXPORT zerosetTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# Every header: the API's include the internal ones.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/zeroset DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.hpp")

set(ZEROSET_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/zeroset)
install(EXPORT zerosetTargets NAMESPACE zeroset:: FILE zerosetTargets.cmake DESTINATION ${ZEROSET_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/zerosetConfig.cmake.in
  ${PROJECT_BINARY_DIR}/zerosetConfig.cmake INSTALL_DESTINATION ${ZEROSET_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/zerosetConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/zerosetConfig.cmake ${PROJECT_BINARY_DIR}/zerosetConfigVersion.cmake
  DESTINATION ${ZEROSET_CMAKE_DIR})

# The .pc file finds the prefix from where it lies, so `--prefix` at install
# time needs no reconfiguring.
file(RELATIVE_PATH ZEROSET_PC_TO_PREFIX /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
configure_file(${CMAKE_CURRENT_LIST_DIR}/zeroset.pc.in ${PROJECT_BINARY_DIR}/zeroset.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/zeroset.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
