# Run by `cmake --install` after the documentation is in place: the README and
# docs/ are written for a checkout (`build/strun`, `docs/cli.md`,
# `programs/x.st`); in the installed copies those become `strun`, the
# installed pages and the installed examples, so that every path they name
# exists after `make install` (issue 29).
# Needs STRUN_DOCDIR (relative to the prefix, e.g. share/doc/strun).
set(docdir "$ENV{DESTDIR}${CMAKE_INSTALL_PREFIX}/${STRUN_DOCDIR}")
set(shown "${CMAKE_INSTALL_PREFIX}/${STRUN_DOCDIR}")
file(GLOB_RECURSE pages "${docdir}/*.md")
foreach(page ${pages})
  file(READ "${page}" text)
  set(before "${text}")
  string(REPLACE "build/strun" "strun" text "${text}")
  string(REGEX REPLACE "([^A-Za-z0-9_./-])docs/" "\\1${shown}/" text "${text}")
  string(REGEX REPLACE "([^A-Za-z0-9_./-])programs/" "\\1${shown}/examples/" text "${text}")
  if(NOT text STREQUAL before)
    file(WRITE "${page}" "${text}")
  endif()
endforeach()
