# The course site's check, without a browser (CI runs it after the docs build):
#
#   cmake -DSITE=build/main/docs/html -DROOT=. -DBUILD=build/main [-DREQUIRE_FIGURES=ON]
#         -P cmake/check_site.cmake
#
# 1. Every relative link (href, src) of every page resolves to a file of the site, and its
#    #anchor to an id or name in that file.
# 2. No page shows raw TeX (\f$, \f[, \_form#), unprocessed Doxygen commands (\ref, \snippet,
#    \include, \anchor), Markdown bold that did not render (a literal **, as when a formula
#    or a \ref sits inside **...**: write <b>...</b> there) or Doxygen's warning text.
# 3. Every chapter page (chNN.html) has its previous/next links at the top and the bottom
#    (to the chapter before and after it: index.html before the first, closing.html after
#    the last), a "Run this now" section (id chNN_run_now), and, with REQUIRE_FIGURES, at
#    least two SVG figures (<img>, <object> or <iframe>).
# 4. No validation-case code (A2, B15, A2b) in a chapter's prose without its link: codes
#    inside links, code spans, listings and formulas are fine. The same rule on the Markdown
#    sources (chapters/, docs/appendices/): a code is written [A2b](@ref case_A2b), and the
#    entry it links exists in docs/validation_catalogue.md.
# 5. Every `ctest --preset P ... -L X` or `-R X` command in the chapters, the docs pages and
#    the README selects at least one test (`ctest --preset P -N`, run from ROOT; exercise
#    entries, which only the exercises preset registers, are matched against the stubs).
# 6. Every term of docs/glossary_terms.txt that the chapters' prose uses 10 times or more has
#    the entries it names in docs/glossary.md (cmake/check_glossary.cmake, included here; it
#    also runs alone: cmake -DROOT=. -P cmake/check_glossary.cmake).
# Every failure is one line naming the page or file; the script fails if there is any.
cmake_minimum_required(VERSION 3.25)
foreach(var SITE ROOT BUILD)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_site.cmake needs -D${var}=...")
  endif()
endforeach()
get_filename_component(SITE "${SITE}" ABSOLUTE)
get_filename_component(ROOT "${ROOT}" ABSOLUTE)
get_filename_component(BUILD "${BUILD}" ABSOLUTE)
if(NOT EXISTS "${SITE}/index.html")
  message(FATAL_ERROR "check_site: no site at ${SITE} (build the docs target first)")
endif()

set_property(GLOBAL PROPERTY site_problems 0)
function(problem text)
  message(NOTICE "check_site: ${text}")
  get_property(count GLOBAL PROPERTY site_problems)
  math(EXPR count "${count} + 1")
  set_property(GLOBAL PROPERTY site_problems ${count})
endfunction()

file(GLOB pages RELATIVE "${SITE}" "${SITE}/*.html")
list(SORT pages)

# --- 1. links and anchors -------------------------------------------------------------
# Anchors of a page, read once: ids and names.
function(anchors_of page out)
  get_property(known GLOBAL PROPERTY "site_anchors_${page}" SET)
  if(NOT known)
    file(READ "${SITE}/${page}" html)
    string(REGEX MATCHALL "(id|name)=\"[^\"]*\"" attrs "${html}")
    set(ids "")
    foreach(attr IN LISTS attrs)
      string(REGEX REPLACE "^(id|name)=\"([^\"]*)\"$" "\\2" id "${attr}")
      list(APPEND ids "${id}")
    endforeach()
    set_property(GLOBAL PROPERTY "site_anchors_${page}" "${ids}")
  endif()
  get_property(ids GLOBAL PROPERTY "site_anchors_${page}")
  set(${out} "${ids}" PARENT_SCOPE)
endfunction()

# `html` without its code listings (Doxygen's <div class="fragment"> ... </div><!-- fragment -->).
function(strip_fragments html out)
  set(result "")
  while(TRUE)
    string(FIND "${html}" "<div class=\"fragment\">" start)
    if(start EQUAL -1)
      break()
    endif()
    string(SUBSTRING "${html}" 0 ${start} before)
    string(APPEND result "${before} ")
    string(SUBSTRING "${html}" ${start} -1 html)
    string(FIND "${html}" "</div><!-- fragment -->" stop)
    if(stop EQUAL -1)
      set(html "")
      break()
    endif()
    math(EXPR stop "${stop} + 23")
    string(SUBSTRING "${html}" ${stop} -1 html)
  endwhile()
  string(APPEND result "${html}")
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

foreach(page IN LISTS pages)
  file(READ "${SITE}/${page}" html)
  string(REGEX MATCHALL "(href|src)=\"[^\"]*\"" links "${html}")
  list(REMOVE_DUPLICATES links)
  foreach(link IN LISTS links)
    string(REGEX REPLACE "^(href|src)=\"([^\"]*)\"$" "\\2" target "${link}")
    if(target MATCHES "^(https?:|mailto:|javascript:|data:|file:)" OR target STREQUAL "")
      continue()
    endif()
    string(REGEX REPLACE "#.*$" "" file_part "${target}")
    set(anchor "")
    if(target MATCHES "#(.+)$")
      set(anchor "${CMAKE_MATCH_1}")
    endif()
    string(REGEX REPLACE "\\?.*$" "" file_part "${file_part}")
    if(file_part STREQUAL "")
      set(file_part "${page}")
    endif()
    if(NOT EXISTS "${SITE}/${file_part}")
      problem("${page}: link to a missing file: ${target}")
      continue()
    endif()
    # Doxygen 1.9.4 links "Classes" in a class's summary to #nested-classes without
    # writing that anchor: its own bug, not the course's.
    if(anchor AND file_part MATCHES "\\.html$" AND NOT anchor STREQUAL "nested-classes")
      anchors_of("${file_part}" ids)
      list(FIND ids "${anchor}" found)
      if(found EQUAL -1)
        problem("${page}: link to a missing anchor: ${target}")
      endif()
    endif()
  endforeach()

  # --- 2. raw TeX, unprocessed commands, warnings ---------------------------------------
  # (Doxygen's own search and navigation scripts are not pages; listings are excluded by
  # the patterns, which need a TeX or Doxygen command followed by its argument.)
  strip_fragments("${html}" prose)
  string(REGEX REPLACE "<code>[^<]*</code>" " " prose "${prose}")
  foreach(pattern "\\\\f\\$" "\\\\f\\[" "\\\\f\\]" "_form#[0-9]" "[^a-z]\\\\ref [a-z]" "\\\\snippet "
                  "\\\\include(\\{doc\\})? " "\\\\anchor " "warning: " "unable to resolve reference"
                  "[ >(]\\*\\*[A-Za-z<]")
    if(prose MATCHES "${pattern}")
      string(REGEX MATCH ".{0,40}${pattern}.{0,40}" context "${prose}")
      string(REPLACE "\n" " " context "${context}")
      problem("${page}: raw markup or a warning (${pattern}): ...${context}...")
    endif()
  endforeach()
endforeach()

# --- 3 and 4. chapter pages ---------------------------------------------------------------
file(GLOB chapter_pages RELATIVE "${SITE}" "${SITE}/ch[0-9][0-9].html")
list(SORT chapter_pages)
if(NOT chapter_pages)
  problem("no chapter pages (chNN.html) in ${SITE}")
endif()
# The chapters' appendix pages (ch09_appendix_pass.html, ch09_all_tests.html,
# ch08_reference.html) have the same navigation and the same rule for case codes; figures
# are asked of chapters only.
file(GLOB appendix_pages RELATIVE "${SITE}" "${SITE}/ch[0-9][0-9]_appendix*.html"
     "${SITE}/ch[0-9][0-9]_all_tests.html" "${SITE}/ch[0-9][0-9]_reference.html")
foreach(page IN LISTS chapter_pages appendix_pages)
  file(READ "${SITE}/${page}" html)
  string(REGEX MATCHALL "class=\"chapter_nav\"" navs "${html}")
  list(LENGTH navs nav_count)
  if(nav_count LESS 2)
    problem("${page}: previous/next links at the top and the bottom expected, found ${nav_count}")
  endif()
  # A chapter's links go to the chapter before it and the one after it (the course map,
  # index.html, before the first; the closing page after the last), at the top and the bottom.
  list(FIND chapter_pages "${page}" chapter_index)
  if(NOT chapter_index EQUAL -1)
    list(LENGTH chapter_pages chapter_count)
    math(EXPR before_index "${chapter_index} - 1")
    math(EXPR after_index "${chapter_index} + 1")
    if(before_index LESS 0)
      set(expected_before "index.html")
    else()
      list(GET chapter_pages ${before_index} expected_before)
    endif()
    if(after_index EQUAL chapter_count)
      set(expected_after "closing.html")
    else()
      list(GET chapter_pages ${after_index} expected_after)
    endif()
    # Every chapter ends with something the reader runs: its "Run this now" section.
    string(REGEX REPLACE "\\.html$" "" chapter_id "${page}")
    if(NOT html MATCHES "id=\"${chapter_id}_run_now\"")
      problem("${page}: no \"Run this now\" section (## Run this now {#${chapter_id}_run_now})")
    endif()
    # Each bar, from its opening tag to the first </div> after it.
    set(rest "${html}")
    while(TRUE)
      string(FIND "${rest}" "<div class=\"chapter_nav\">" start)
      if(start EQUAL -1)
        break()
      endif()
      string(SUBSTRING "${rest}" ${start} -1 rest)
      string(FIND "${rest}" "</div>" stop)
      string(SUBSTRING "${rest}" 0 ${stop} nav)
      string(SUBSTRING "${rest}" 1 -1 rest)
      foreach(expected IN ITEMS "${expected_before}" "${expected_after}")
        string(FIND "${nav}" "href=\"${expected}" found)
        if(found EQUAL -1)
          problem("${page}: a previous/next bar without its link to ${expected}")
        endif()
      endforeach()
    endwhile()
  endif()
  # <img>/<object>: \image html and the htmlonly figures; <iframe>: \dotfile (Graphviz).
  string(REGEX MATCHALL "<(img|object|iframe)[^>]*\\.svg" figures "${html}")
  list(LENGTH figures figure_count)
  list(FIND chapter_pages "${page}" is_chapter)
  if(REQUIRE_FIGURES AND NOT is_chapter EQUAL -1 AND figure_count LESS 2)
    problem("${page}: at least two SVG figures expected, found ${figure_count}")
  endif()
  # Prose and code spans: drop listings, links, formulas and tags, then look for codes.
  # Code spans stay in: a test name such as "A6 masses 1 and 3 ..." carries its case code
  # as a link inside the span (<code>\ref case_A6 "A6" masses ...</code> in the source).
  set(text "${html}")
  strip_fragments("${text}" text)
  string(REGEX REPLACE "<pre[^>]*>[^<]*</pre>" " " text "${text}")
  string(REGEX REPLACE "<a [^>]*>[^<]*</a>" " " text "${text}")
  string(REGEX REPLACE "\\\\\\([^\\\\]*\\\\\\)" " " text "${text}")
  string(REGEX REPLACE "<[^>]*>" " " text "${text}")
  string(REGEX MATCHALL "[^A-Za-z0-9_#./-][AB][0-9][0-9]?[a-z]?[^A-Za-z0-9_]" codes "${text}")
  foreach(code IN LISTS codes)
    string(REGEX MATCH "[AB][0-9]+[a-z]?" code "${code}")
    string(FIND "${text}" "${code}" at)
    math(EXPR at "${at} - 60")
    if(at LESS 0)
      set(at 0)
    endif()
    string(SUBSTRING "${text}" ${at} 140 context)
    string(REGEX REPLACE "[ \n\t]+" " " context "${context}")
    problem("${page}: validation case ${code} in the prose without a link to its catalogue entry: ...${context}...")
  endforeach()
endforeach()

# --- 4b. case codes in the Markdown sources ----------------------------------------------
# The same rule on the sources of the chapters and their appendix pages, so that the raw
# Markdown and the built site agree: a case code is written as a link to its catalogue
# entry, [A2b](@ref case_A2b) (or [B5a](@ref case_B5) for a variant of a case), and the
# entry exists. Formulas, listings and page or section ids are not prose.
file(READ "${ROOT}/docs/validation_catalogue.md" catalogue)
string(REGEX MATCHALL "\\{#case_[A-Za-z0-9]+\\}" catalogue_ids "${catalogue}")
file(GLOB case_sources "${ROOT}/chapters/*.md" "${ROOT}/docs/appendices/*.md")
list(SORT case_sources)
foreach(source IN LISTS case_sources)
  file(RELATIVE_PATH shown "${ROOT}" "${source}")
  file(READ "${source}" text)
  string(REGEX MATCHALL "\\[[^]\n]*\\]\\(@ref case_[A-Za-z0-9]+\\)" case_links "${text}")
  list(REMOVE_DUPLICATES case_links)
  foreach(link IN LISTS case_links)
    string(REGEX REPLACE "^\\[([^]]*)\\]\\(@ref case_([A-Za-z0-9]+)\\)$" "\\1;\\2" parts "${link}")
    list(GET parts 0 link_text)
    list(GET parts 1 link_case)
    list(FIND catalogue_ids "{#case_${link_case}}" known)
    if(known EQUAL -1)
      problem("${shown}: ${link} links to no entry of docs/validation_catalogue.md")
    elseif(NOT link_text MATCHES "^${link_case}[a-z]?$")
      problem("${shown}: ${link}: the link text is not the code of the case it links")
    endif()
  endforeach()
  string(REGEX REPLACE "\\[[^]\n]*\\]\\(@ref case_[A-Za-z0-9]+\\)" " " text "${text}")
  string(REGEX REPLACE "\\\\f\\$[^$]*\\\\f\\$" " " text "${text}")
  string(REGEX REPLACE "\\\\f\\[[^]]*\\\\f\\]" " " text "${text}")
  string(REGEX REPLACE "\\{#[^}]*\\}" " " text "${text}")
  string(REGEX REPLACE "\n[ \t]*\\\\(snippet|include|verbinclude|image|dotfile)[^\n]*" "\n" text "${text}")
  string(REGEX MATCHALL "[^A-Za-z0-9_#./[-][AB][0-9][0-9]?[a-z]?[^A-Za-z0-9_]" codes " ${text} ")
  foreach(code IN LISTS codes)
    string(REGEX MATCH "[AB][0-9]+[a-z]?" code "${code}")
    problem("${shown}: validation case ${code} without a link to its catalogue entry (write [${code}](@ref case_${code}))")
  endforeach()
endforeach()

# --- 5. ctest commands shown to the reader -----------------------------------------------
file(GLOB text_sources "${ROOT}/chapters/*.md" "${ROOT}/docs/*.md" "${ROOT}/docs/appendices/*.md")
list(APPEND text_sources "${ROOT}/README.md")
set(checked "")
foreach(source IN LISTS text_sources)
  file(READ "${source}" text)
  file(RELATIVE_PATH shown "${ROOT}" "${source}")
  string(REGEX MATCHALL "ctest --preset [a-z]+( [^`\n|]*)? -[LR] [A-Za-z0-9_.|-]+" commands "${text}")
  foreach(command IN LISTS commands)
    if(NOT command MATCHES "^ctest --preset ([a-z]+).* -([LR]) ([A-Za-z0-9_.|-]+)$")
      continue()
    endif()
    set(preset "${CMAKE_MATCH_1}")
    set(kind "${CMAKE_MATCH_2}")
    set(selector "${CMAKE_MATCH_3}")
    if(selector MATCHES "(NN|N\\.M)")
      continue()  # a pattern for the reader to fill in, such as chNN or exNN.M
    endif()
    list(FIND checked "${preset} -${kind} ${selector}" seen)
    if(NOT seen EQUAL -1)
      continue()
    endif()
    list(APPEND checked "${preset} -${kind} ${selector}")
    if(preset STREQUAL "exercises")
      # The exercises preset has its own build; its entries are exNN.M, one per stub,
      # labelled exercise and chNN.
      if(kind STREQUAL "R" AND selector MATCHES "^ex([0-9][0-9])\\.([0-9]+)$")
        file(GLOB stub "${ROOT}/src/stackbook/exercises/ex${CMAKE_MATCH_1}_${CMAKE_MATCH_2}_*.cpp")
      elseif(kind STREQUAL "L" AND selector MATCHES "^ch([0-9][0-9])$")
        file(GLOB stub "${ROOT}/src/stackbook/exercises/ex${CMAKE_MATCH_1}_*.cpp")
      elseif(kind STREQUAL "L" AND selector STREQUAL "exercise")
        file(GLOB stub "${ROOT}/src/stackbook/exercises/ex*.cpp")
      else()
        set(stub "")
      endif()
      if(NOT stub)
        problem("${shown}: `${command}` selects no exercise")
      endif()
      continue()
    endif()
    execute_process(COMMAND ctest --preset ${preset} -N -${kind} ${selector}
                    WORKING_DIRECTORY "${ROOT}" OUTPUT_VARIABLE listing ERROR_VARIABLE listing
                    RESULT_VARIABLE result)
    if(NOT listing MATCHES "Total Tests: ([0-9]+)" OR CMAKE_MATCH_1 EQUAL 0)
      problem("${shown}: `${command}` selects no test")
    endif()
  endforeach()
endforeach()

# --- 6. the glossary's terms ---------------------------------------------------------------
include("${CMAKE_CURRENT_LIST_DIR}/check_glossary.cmake")

list(LENGTH pages page_count)
list(LENGTH checked command_count)
get_property(problems GLOBAL PROPERTY site_problems)
if(problems GREATER 0)
  message(FATAL_ERROR "check_site: ${problems} problems in ${page_count} pages")
endif()
message(STATUS "check_site: ${page_count} pages, ${command_count} ctest commands and ${glossary_term_count} glossary terms checked, no problems")
