# What `cmake --install build [--prefix P]` puts where (GNUInstallDirs; the default prefix is /usr/local):
#   include/ede/*.hpp           the public headers, the only ones a program needs (examples/hello)
#   lib/libede.a                the library
#   lib/cmake/ede/              the CMake package: find_package(ede) -> ede::ede
#   lib/pkgconfig/ede.pc        the same for pkg-config (link a static library with --static)
#   bin/ede-*                   the tools
#   share/ede/plot/*.py         the plotting scripts the tools run (found from bin/ at run time: tools/common/plot_runner.cpp)
#   share/man/man1/*.1          the tools' manual pages, where help2man is installed (cmake/EdeManPages.cmake)
# Everything is relocatable: the CMake package and ede.pc locate the prefix from their own place.
include(CMakePackageConfigHelpers)

set(EDE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/ede)
set(EDE_XXHASH_MIN_VERSION 0.8)

install(TARGETS ede EXPORT edeTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/libede/include/ede DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(EXPORT edeTargets NAMESPACE ede:: DESTINATION ${EDE_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/edeConfig.cmake.in ${PROJECT_BINARY_DIR}/edeConfig.cmake
                              INSTALL_DESTINATION ${EDE_CMAKE_DIR})
# 0.x: a new minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/edeConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/edeConfig.cmake ${PROJECT_BINARY_DIR}/edeConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/Findxxhash.cmake DESTINATION ${EDE_CMAKE_DIR})

file(RELATIVE_PATH EDE_PC_PREFIX_FROM_PCDIR /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(REGEX REPLACE "/$" "" EDE_PC_PREFIX_FROM_PCDIR "${EDE_PC_PREFIX_FROM_PCDIR}")
set(EDE_PC_QUADMATH "")
if(EDE_HAVE_FLOAT128)
  set(EDE_PC_QUADMATH " -lquadmath")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/ede.pc.in ${PROJECT_BINARY_DIR}/ede.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/ede.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# ede-bench-elastic too: `ede-bench effects` runs it from ede-bench's own directory.
set(EDE_INSTALLED_TOOLS ede-sim ede-replay ede-stats ede-crater ede-render ede-sweep ede-bench ede-bench-elastic ede-view)
foreach(tool IN LISTS EDE_INSTALLED_TOOLS)
  if(TARGET ${tool})
    install(TARGETS ${tool} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endforeach()
file(GLOB EDE_PLOT_SCRIPTS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tools/plot/*.py)
install(FILES ${EDE_PLOT_SCRIPTS} DESTINATION ${CMAKE_INSTALL_DATADIR}/ede/plot)

include(${CMAKE_CURRENT_LIST_DIR}/EdeManPages.cmake)
