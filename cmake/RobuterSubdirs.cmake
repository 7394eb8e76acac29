# SPDX-License-Identifier: GPL-3.0-or-later
# robuter_add_subfolders(): adds every direct sub-folder that has its own CMakeLists.txt, so a
# new part of the project is one new folder (the parent lists are never edited).
function(robuter_add_subfolders)
  file(GLOB _children RELATIVE ${CMAKE_CURRENT_SOURCE_DIR} CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*/CMakeLists.txt)
  list(SORT _children)
  foreach(_c ${_children})
    get_filename_component(_d ${_c} DIRECTORY)
    add_subdirectory(${_d})
  endforeach()
endfunction()
