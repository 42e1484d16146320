# The public C++ API as a shared library (libsymmesh.so, src/symmesh/symmesh.h, docs/api.md), the
# installed CMake package (find_package(symmesh), target symmesh::symmesh) and the Python module.
# Included from the top-level CMakeLists.txt once every library target and the CLI exist.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# libsymmesh.so and the Python module link the static layers in, so they must be
# position-independent (a -fPIE object cannot go into a shared object).
set_target_properties(symmesh_number symmesh_core symmesh_gen symmesh_fem symmesh_io
  PROPERTIES POSITION_INDEPENDENT_CODE ON)

# One generation run for `symmesh generate` and the API (api/generate_run.h).
add_library(symmesh_run STATIC src/symmesh/api/generate_run.cpp)
set_target_properties(symmesh_run PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_link_libraries(symmesh_run PUBLIC symmesh_io PRIVATE symmesh_warnings)
target_link_libraries(symmesh PRIVATE symmesh_run)

# Its dependencies are linked in privately and their symbols kept local (--exclude-libs), so a
# program using symmesh.h needs neither their headers nor their CMake packages: the config file
# has nothing to find_dependency.
add_library(symmesh_api SHARED src/symmesh/api/symmesh.cpp)
add_library(symmesh::symmesh ALIAS symmesh_api)
set_target_properties(symmesh_api PROPERTIES OUTPUT_NAME symmesh EXPORT_NAME symmesh
  VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}
  CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
target_compile_definitions(symmesh_api PRIVATE SYMMESH_VERSION="${PROJECT_VERSION}")
target_include_directories(symmesh_api INTERFACE
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
target_compile_features(symmesh_api INTERFACE cxx_std_17)
target_link_libraries(symmesh_api PRIVATE symmesh_run symmesh_warnings)
target_link_options(symmesh_api PRIVATE -Wl,--exclude-libs,ALL)
# Every symbol resolved at link time, not at a user's first call; the sanitizer runtimes of the
# fuzz build are only linked into executables.
if(NOT SYMMESH_FUZZ)
  target_link_options(symmesh_api PRIVATE -Wl,--no-undefined)
endif()

# The Gmsh and PETSc modules go to LIBDIR/symmesh/, where libsymmesh.so looks for them beside
# itself (mesh/module_path.h).
set(SYMMESH_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/symmesh)
install(TARGETS symmesh_api EXPORT symmeshTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS symmesh_gmsh symmesh_petsc LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/symmesh)
install(FILES src/symmesh/symmesh.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/symmesh)
install(EXPORT symmeshTargets NAMESPACE symmesh:: DESTINATION ${SYMMESH_INSTALL_CMAKEDIR})
configure_package_config_file(cmake/symmeshConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/symmeshConfig.cmake INSTALL_DESTINATION ${SYMMESH_INSTALL_CMAKEDIR}
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR)
# 0.x: a minor version may change the API, so only the same major and minor are compatible.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/symmeshConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/symmeshConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/symmeshConfigVersion.cmake DESTINATION ${SYMMESH_INSTALL_CMAKEDIR})

add_subdirectory(python)
