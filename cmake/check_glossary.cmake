# The glossary's check: every term the chapters use often has its glossary entry.
#
#   cmake -DROOT=. [-DGLOSSARY_COUNTS=ON] -P cmake/check_glossary.cmake
#
# docs/glossary_terms.txt lists the course's terms, one a line, each with the entries of
# docs/glossary.md that cover it ("island = Island"; see the top of that file). For every
# term, the script counts its uses in the prose of chapters/*.md: case-insensitive, whole
# words, a plural in s or es allowed, hyphens and apostrophes taken as word breaks. Prose is
# the text without formulas (\f$..\f$, \f[..\f], \f{..\f}), listings (``` or ~~~ fences,
# \code, \verbatim, \htmlonly), code spans, HTML tags, {#ids}, link targets and Doxygen
# commands (\ref and \anchor with their argument; \snippet, \include, \image, \dotfile lines).
# A term used GLOSSARY_MIN_USES times (10) or more whose entry is missing is one line:
#
#   docs/glossary_terms.txt: term "X" is used N times in the chapters but docs/glossary.md has no entry "Y"
#
# A glossary entry is a paragraph that begins **Name.** or **Name** (a symbol may follow).
# With GLOSSARY_COUNTS=ON the script also prints every term's count, to help keep the list.
# cmake/check_site.cmake include()s this file as its check 6: its problem() then collects
# the lines. Run alone, the script fails if there is any.
cmake_minimum_required(VERSION 3.25)
if(NOT DEFINED ROOT)
  message(FATAL_ERROR "check_glossary.cmake needs -DROOT=...")
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)
if(NOT DEFINED GLOSSARY_MIN_USES)
  set(GLOSSARY_MIN_USES 10)
endif()

set(glossary_standalone FALSE)
if(NOT COMMAND problem)
  set(glossary_standalone TRUE)
  set_property(GLOBAL PROPERTY glossary_problems 0)
  function(problem text)
    message(NOTICE "check_glossary: ${text}")
    get_property(count GLOBAL PROPERTY glossary_problems)
    math(EXPR count "${count} + 1")
    set_property(GLOBAL PROPERTY glossary_problems ${count})
  endfunction()
endif()

# `text` without every span from `open` to the next `close` (both included).
function(glossary_strip_spans text open close out)
  set(result "")
  string(LENGTH "${open}" open_length)
  string(LENGTH "${close}" close_length)
  while(TRUE)
    string(FIND "${text}" "${open}" start)
    if(start EQUAL -1)
      break()
    endif()
    string(SUBSTRING "${text}" 0 ${start} before)
    string(APPEND result "${before} ")
    math(EXPR start "${start} + ${open_length}")
    string(SUBSTRING "${text}" ${start} -1 text)
    string(FIND "${text}" "${close}" stop)
    if(stop EQUAL -1)
      set(text "")
      break()
    endif()
    math(EXPR stop "${stop} + ${close_length}")
    string(SUBSTRING "${text}" ${stop} -1 text)
  endwhile()
  string(APPEND result "${text}")
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

# Lower case, words of [a-z0-9] only, two spaces between words and one at each end, so that
# " word " matches a whole word and consecutive words both match.
function(glossary_words text out)
  string(TOLOWER "${text}" text)
  string(REGEX REPLACE "[^a-z0-9]+" "  " text "${text}")
  set(${out} " ${text} " PARENT_SCOPE)
endfunction()

# --- the glossary's entries ----------------------------------------------------------------
set(glossary_file "${ROOT}/docs/glossary.md")
set(glossary_terms_file "${ROOT}/docs/glossary_terms.txt")
file(READ "${glossary_file}" glossary_text)
string(REGEX MATCHALL "(^|\n)\\*\\*[^*\n]+\\*\\*" glossary_heads "${glossary_text}")
set(glossary_entries "")
foreach(glossary_head IN LISTS glossary_heads)
  string(REGEX REPLACE "^\n?\\*\\*([^*]+)\\*\\*$" "\\1" glossary_name "${glossary_head}")
  string(REGEX REPLACE "\\.$" "" glossary_name "${glossary_name}")
  string(STRIP "${glossary_name}" glossary_name)
  list(APPEND glossary_entries "${glossary_name}")
endforeach()

# --- the chapters' prose --------------------------------------------------------------------
file(GLOB glossary_chapters "${ROOT}/chapters/*.md")
list(SORT glossary_chapters)
set(glossary_prose "")
foreach(glossary_chapter IN LISTS glossary_chapters)
  file(READ "${glossary_chapter}" glossary_text)
  # (Pairs written out one by one: a CMake list does not split inside [ and ].)
  glossary_strip_spans("${glossary_text}" "```" "```" glossary_text)
  glossary_strip_spans("${glossary_text}" "~~~" "~~~" glossary_text)
  glossary_strip_spans("${glossary_text}" "\\code" "\\endcode" glossary_text)
  glossary_strip_spans("${glossary_text}" "\\verbatim" "\\endverbatim" glossary_text)
  glossary_strip_spans("${glossary_text}" "\\htmlonly" "\\endhtmlonly" glossary_text)
  glossary_strip_spans("${glossary_text}" "\\f$" "\\f$" glossary_text)
  glossary_strip_spans("${glossary_text}" "\\f[" "\\f]" glossary_text)
  glossary_strip_spans("${glossary_text}" "\\f{" "\\f}" glossary_text)
  string(REGEX REPLACE "`[^`\n]*`" " " glossary_text "${glossary_text}")
  string(REGEX REPLACE "\n[ \t]*\\\\(snippet|include|image|dotfile|verbinclude)[^\n]*" "\n" glossary_text "\n${glossary_text}")
  string(REGEX REPLACE "[\\\\@](ref|anchor|label|cite)[ \t]+[^ \t\n]+" " " glossary_text "${glossary_text}")
  string(REGEX REPLACE "\\\\[A-Za-z]+" " " glossary_text "${glossary_text}")
  string(REGEX REPLACE "\\{#[^}]*\\}" " " glossary_text "${glossary_text}")
  string(REGEX REPLACE "\\]\\([^)\n]*\\)" " " glossary_text "${glossary_text}")
  string(REGEX REPLACE "<[^>\n]*>" " " glossary_text "${glossary_text}")
  string(APPEND glossary_prose "${glossary_text}\n")
endforeach()
glossary_words("${glossary_prose}" glossary_prose)

# --- the terms -------------------------------------------------------------------------------
file(STRINGS "${glossary_terms_file}" glossary_lines ENCODING UTF-8)
set(glossary_term_count 0)
set(glossary_line_number 0)
foreach(glossary_line IN LISTS glossary_lines)
  math(EXPR glossary_line_number "${glossary_line_number} + 1")
  string(STRIP "${glossary_line}" glossary_line)
  if(glossary_line STREQUAL "" OR glossary_line MATCHES "^#")
    continue()
  endif()
  if(NOT glossary_line MATCHES "^([^=]+)=(.+)$")
    problem("docs/glossary_terms.txt:${glossary_line_number}: not `term = Entry`: ${glossary_line}")
    continue()
  endif()
  string(STRIP "${CMAKE_MATCH_1}" glossary_term)
  string(REPLACE "|" ";" glossary_wanted "${CMAKE_MATCH_2}")
  math(EXPR glossary_term_count "${glossary_term_count} + 1")
  glossary_words("${glossary_term}" glossary_pattern)
  string(STRIP "${glossary_pattern}" glossary_pattern)
  string(REGEX MATCHALL " ${glossary_pattern}(e?s)? " glossary_uses "${glossary_prose}")
  list(LENGTH glossary_uses glossary_uses)
  if(GLOSSARY_COUNTS)
    message(NOTICE "${glossary_uses}\t${glossary_term}")
  endif()
  if(glossary_uses LESS GLOSSARY_MIN_USES)
    continue()
  endif()
  foreach(glossary_entry IN LISTS glossary_wanted)
    string(STRIP "${glossary_entry}" glossary_entry)
    list(FIND glossary_entries "${glossary_entry}" glossary_found)
    if(glossary_found EQUAL -1)
      problem("docs/glossary_terms.txt: term \"${glossary_term}\" is used ${glossary_uses} times in the chapters but docs/glossary.md has no entry \"${glossary_entry}\"")
    endif()
  endforeach()
endforeach()

if(glossary_standalone)
  get_property(glossary_problems GLOBAL PROPERTY glossary_problems)
  if(glossary_problems GREATER 0)
    message(FATAL_ERROR "check_glossary: ${glossary_problems} problems in ${glossary_term_count} terms")
  endif()
  list(LENGTH glossary_entries glossary_entry_count)
  message(STATUS "check_glossary: ${glossary_term_count} terms against ${glossary_entry_count} entries checked, no problems")
endif()
