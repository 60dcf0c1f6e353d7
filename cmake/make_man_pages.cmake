# Writes the manual pages of one tool with help2man, from the tool's own --help and --version, so that a
# page can never say what the tool does not: TOOL.1, and one page per subcommand in git's style
# (ede-replay-state.1) whose SEE ALSO names the tool's page. Run by the build (cmake/EdeManPages.cmake):
#   cmake -DTOOL=path/to/ede-replay -DHELP2MAN=help2man -DOUT_DIR=dir -DSTAMP=file -P make_man_pages.cmake
# OUT_DIR is the tool's own folder, emptied first, so that a subcommand removed leaves no page behind.
# The tool runs by its bare name with its own folder first on PATH, so usage lines name it as a user types
# it, not by the build's path. (Rejected: one page per tool with each subcommand's help pasted in as
# preformatted text; help2man's pages per subcommand keep man's formatting of options.)
cmake_minimum_required(VERSION 3.25)
get_filename_component(tool_dir "${TOOL}" DIRECTORY)
get_filename_component(tool "${TOOL}" NAME)
set(ENV{PATH} "${tool_dir}:$ENV{PATH}")

function(run_tool out)
  execute_process(COMMAND ${tool} ${ARGN} OUTPUT_VARIABLE text RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "man pages: '${tool} ${ARGN}' exited with ${status}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# "ede-replay, ede 0.1.0" (tools/common/command_line.cpp): the version help2man prints in the footer.
run_tool(version_text --version)
if(NOT version_text MATCHES "^${tool}, ede ([^\n]+)")
  message(FATAL_ERROR "man pages: '${tool} --version' printed '${version_text}', not '${tool}, ede VERSION'")
endif()
set(version "${CMAKE_MATCH_1}")

# The first line of --help is "TOOL: what it does"; the lines after "Subcommands:" name the subcommands.
run_tool(help_text --help)
string(REGEX MATCH "^${tool} ?: ([^\n]+)" _ "${help_text}")
set(summary "${CMAKE_MATCH_1}")
set(subcommands "")
string(FIND "${help_text}" "\nSubcommands:\n" at)
if(at GREATER -1)
  string(SUBSTRING "${help_text}" ${at} -1 listing)
  string(REGEX MATCHALL "\n  [a-z0-9-]+ " names "${listing}")
  foreach(name IN LISTS names)
    string(STRIP "${name}" name)
    list(APPEND subcommands "${name}")
  endforeach()
endif()

function(help2man page program name_line see_also)
  set(include_file "${OUT_DIR}/${page}.h2m")
  file(WRITE "${include_file}" "[SEE ALSO]\n${see_also}\n")
  execute_process(COMMAND ${HELP2MAN} --no-info --name "${name_line}"
                          --version-string "${page} (ede) ${version}" --include "${include_file}"
                          --output "${OUT_DIR}/${page}.1" "${program}"
                  RESULT_VARIABLE status ERROR_VARIABLE errors)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "man pages: help2man failed for '${program}': ${errors}")
  endif()
  file(REMOVE "${include_file}")
endfunction()

file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")
set(see_also "The command-line language every tool shares: docs/cli.md in ede's sources.")
set(sub_pages "")
foreach(sub IN LISTS subcommands)
  run_tool(sub_help ${sub} --help)
  string(REGEX MATCH "^[^\n]*" sub_summary "${sub_help}")
  if(sub_summary STREQUAL "" OR sub_summary MATCHES "^Usage:")
    set(sub_summary "${tool} ${sub}")
  endif()
  help2man(${tool}-${sub} "${tool} ${sub}" "${sub_summary}" ".BR ${tool} (1)\n.PP\n${see_also}")
  string(APPEND sub_pages ".BR ${tool}-${sub} (1),\n")
endforeach()
string(REGEX REPLACE ",\n$" "\n" sub_pages "${sub_pages}")
help2man(${tool} ${tool} "${summary}" "${sub_pages}.PP\n${see_also}")
file(WRITE "${STAMP}" "${tool} ${version}: ${tool}.1 ${subcommands}\n")
