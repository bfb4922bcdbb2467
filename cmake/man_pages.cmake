# Writes the man pages into DIR: scalcal.1 and scalcal-NAME.1 for every NAME of COMMANDS (a comma
# list), each what `SCALCAL --man [NAME]` prints (experiments/cli/man_page.cpp). Run by the build
# (experiments/CMakeLists.txt), so the pages are made from the very option tables of the binary.
string(REPLACE "," ";" names "${COMMANDS}")
# A sanitizer build outside scripts/sanitize.sh (which sets LSan's suppressions) could fail this step on
# CLN's static allocation (scripts/lsan.supp): the pages are text; leaks are the test suite's concern.
if(NOT DEFINED ENV{ASAN_OPTIONS})
  set(ENV{ASAN_OPTIONS} "detect_leaks=0")
endif()
file(MAKE_DIRECTORY "${DIR}")
foreach(name "" ${names})
  if(name STREQUAL "")
    set(page "${DIR}/scalcal.1")
  else()
    set(page "${DIR}/scalcal-${name}.1")
  endif()
  execute_process(COMMAND "${SCALCAL}" --man ${name} OUTPUT_FILE "${page}.new" RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    file(REMOVE "${page}.new")
    message(FATAL_ERROR "scalcal --man ${name} failed (${status})")
  endif()
  file(RENAME "${page}.new" "${page}")
endforeach()
