# poinsot_set_warnings(target): the project's warning flags, errors unless POINSOT_WERROR is OFF.
function(poinsot_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
                                           -Wnon-virtual-dtor -Wold-style-cast -Woverloaded-virtual)
  if(POINSOT_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
