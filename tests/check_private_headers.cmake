# Checks that a stage's private headers (core/<stage>/detail/) stay in their stage: an
# `#include "core/STAGE/detail/..."` may appear only in core/STAGE/'s sources and its private
# headers, and in its unit tests (tests/unit/STAGE/). It fails, naming the file and line, when
# another stage, app/, ui/, another test or one of the stage's own public headers (core/STAGE/
# outside detail/, which would hand the private header to everyone who includes it) includes one.
# Run by ctest (docs.PrivateHeadersStayInTheirStage): cmake -DROOT=<source dir> -P
# check_private_headers.cmake. See docs/architecture.md, "Rules the code follows".
cmake_minimum_required(VERSION 3.20)
if(NOT ROOT)
  message(FATAL_ERROR "give -DROOT=<the source folder>")
endif()

set(patterns)
foreach(top core app ui tests)
  foreach(ext cpp hpp h cc cxx c inl ipp)
    list(APPEND patterns ${ROOT}/${top}/*.${ext})
  endforeach()
endforeach()
file(GLOB_RECURSE files RELATIVE ${ROOT} ${patterns})
list(SORT files)
# ctest runs this from the build folder: finding no file means the scan looked in the wrong place,
# not that the tree is clean.
if(NOT files)
  message(FATAL_ERROR "no source files under ${ROOT}/core, app, ui or tests")
endif()

set(include_regex "\n[ \t]*#[ \t]*include[ \t]*[\"<]core/([a-z0-9_]+)/detail/[^\">\n]*[\">]")
set(problems)
set(checked 0)
foreach(file IN LISTS files)
  # A cheap look first; most files include no private header.
  file(STRINGS ${ROOT}/${file} candidates REGEX "include[ \t]*[\"<]core/[a-z0-9_]+/detail/")
  if(NOT candidates)
    continue()
  endif()
  file(READ ${ROOT}/${file} content)
  # A leading newline lets the pattern find an include on the first line too; line numbers below
  # count it as the end of line 0.
  string(PREPEND content "\n")
  string(REGEX MATCHALL "${include_regex}" matches "${content}")
  set(cursor 0)
  foreach(match IN LISTS matches)
    math(EXPR checked "${checked} + 1")
    string(REGEX REPLACE "${include_regex}" "\\1" stage "${match}")
    # Where this include is (after the previous one), for its line number.
    string(SUBSTRING "${content}" ${cursor} -1 rest)
    string(FIND "${rest}" "${match}" offset)
    math(EXPR position "${cursor} + ${offset}")
    string(LENGTH "${match}" match_length)
    math(EXPR cursor "${position} + ${match_length}")
    math(EXPR prefix_length "${position} + 1")
    string(SUBSTRING "${content}" 0 ${prefix_length} prefix)
    string(LENGTH "${prefix}" with_newlines)
    string(REPLACE "\n" "" without "${prefix}")
    string(LENGTH "${without}" without_newlines)
    math(EXPR line "${with_newlines} - ${without_newlines}")

    set(allowed FALSE)
    if(file MATCHES "^tests/unit/${stage}/")
      set(allowed TRUE)
    elseif(file MATCHES "^core/${stage}/detail/")
      set(allowed TRUE)
    elseif(file MATCHES "^core/${stage}/" AND NOT file MATCHES "\\.(hpp|h|inl|ipp)$")
      set(allowed TRUE)
    endif()
    if(NOT allowed)
      string(STRIP "${match}" text)
      if(file MATCHES "^core/${stage}/")
        set(why "a public header of core/${stage}/ must not include its private headers")
      else()
        set(why "only core/${stage}/ and tests/unit/${stage}/ may include core/${stage}/detail/")
      endif()
      list(APPEND problems "${file}:${line}: ${text}: ${why}")
    endif()
  endforeach()
endforeach()

if(problems)
  list(JOIN problems "\n" text)
  message(FATAL_ERROR "private headers included outside their stage:\n${text}")
endif()
list(LENGTH files count)
message(STATUS "${checked} includes of core/*/detail/ headers in ${count} files, all from their own stage")
