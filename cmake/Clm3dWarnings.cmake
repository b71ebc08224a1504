# One place for the warning set, so every target of the project is held to the same standard.
function(clm3d_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wold-style-cast -Wcast-align -Woverloaded-virtual
                                           -Wimplicit-fallthrough)
  if(CLM3D_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
