# The viewer's page (viewer/: template, style, scripts) and three.js (Debian's libjs-three, r111, a plain
# script that defines THREE) are compiled into the library as text (cmake/PoinsotEmbedText.cmake), so that
# io/view/view_page.hpp writes a self-contained view.html with no file to find at run time. Without libjs-three the
# library still builds; writing a page then throws InvalidInput saying what to install.
set(POINSOT_THREE_JS "/usr/share/javascript/three/three.min.js" CACHE FILEPATH
    "three.js (non-module build) inlined into view.html; Debian package libjs-three")
set(_viewer_dir ${PROJECT_SOURCE_DIR}/viewer)
file(GLOB _viewer_files CONFIGURE_DEPENDS ${_viewer_dir}/*.html ${_viewer_dir}/*.css ${_viewer_dir}/js/*.js)
set(_assets "")
foreach(_f IN LISTS _viewer_files)
  file(RELATIVE_PATH _rel ${_viewer_dir} ${_f})
  list(APPEND _assets "${_rel}=${_f}")
endforeach()
set(_deps ${_viewer_files})
if(EXISTS ${POINSOT_THREE_JS})
  list(APPEND _assets "three.min.js=${POINSOT_THREE_JS}")
  list(APPEND _deps ${POINSOT_THREE_JS})
else()
  message(STATUS "poinsot: ${POINSOT_THREE_JS} not found (Debian package libjs-three): view.html disabled")
endif()
string(REPLACE ";" "|" _assets_arg "${_assets}")
set(_out ${PROJECT_BINARY_DIR}/generated/view_assets.cpp)
add_custom_command(OUTPUT ${_out}
  COMMAND ${CMAKE_COMMAND} -DOUT=${_out} "-DASSETS=${_assets_arg}" -P ${PROJECT_SOURCE_DIR}/cmake/PoinsotEmbedText.cmake
  DEPENDS ${_deps} ${PROJECT_SOURCE_DIR}/cmake/PoinsotEmbedText.cmake
  COMMENT "Embedding the viewer's page and three.js" VERBATIM)
target_sources(poinsot PRIVATE ${_out})
set_source_files_properties(${_out} PROPERTIES INCLUDE_DIRECTORIES ${PROJECT_SOURCE_DIR}/src/io/view)
