# Manual pages for the tools `cmake --install` puts on the PATH: made at build time by help2man from each
# tool's own --help and --version (cmake/make_man_pages.cmake), so they cannot drift from the tools; one
# page per tool and one per subcommand (`man ede-replay`, `man ede-replay-state`), installed into
# share/man/man1. Part of the default build (target ede_man_pages), not of the demo's few targets.
# Without help2man (scripts/install-deps.sh installs it) the build goes on without pages and says so.
# (Rejected: pages written by hand, which drift; pages committed to the tree, which need a step to redo.)
# Sanitizer and fuzzing builds install nothing for users and would run their tools under the sanitizers
# at build time: no pages there.
if(EDE_SANITIZE OR EDE_FUZZ)
  return()
endif()
find_program(EDE_HELP2MAN help2man)
if(NOT EDE_HELP2MAN)
  message(STATUS "help2man not found (apt-get install help2man): the manual pages are not built")
  return()
endif()

set(EDE_MAN_DIR ${PROJECT_BINARY_DIR}/man)
set(EDE_MAN_STAMPS "")
foreach(tool IN LISTS EDE_INSTALLED_TOOLS)
  if(TARGET ${tool})
    set(stamp ${EDE_MAN_DIR}/${tool}.stamp)
    add_custom_command(OUTPUT ${stamp}
      COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:${tool}> -DHELP2MAN=${EDE_HELP2MAN}
              -DOUT_DIR=${EDE_MAN_DIR}/${tool} -DSTAMP=${stamp} -P ${CMAKE_CURRENT_LIST_DIR}/make_man_pages.cmake
      DEPENDS ${tool} ${CMAKE_CURRENT_LIST_DIR}/make_man_pages.cmake
      COMMENT "Manual pages of ${tool} (help2man)"
      VERBATIM)
    list(APPEND EDE_MAN_STAMPS ${stamp})
  endif()
endforeach()
add_custom_target(ede_man_pages ALL DEPENDS ${EDE_MAN_STAMPS})

# The pages' names are known only once the tools have listed their subcommands, so they are gathered at
# install time.
install(CODE "
  file(GLOB_RECURSE ede_man_pages \"${EDE_MAN_DIR}/*.1\")
  file(INSTALL \${ede_man_pages} DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_MANDIR}/man1\")")
