# Compiles a resource file into a C++ function returning its text, so that the built-in landmark
# scheme works wherever the binary is copied, with no data directory to find.
function(clm3d_embed_text target file symbol)
  set(out ${CMAKE_CURRENT_BINARY_DIR}/embedded_${symbol}.cpp)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${file})
  file(READ ${file} content HEX)
  string(LENGTH "${content}" hex_length)
  math(EXPR byte_count "${hex_length} / 2")
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${content}")
  file(WRITE ${out}.tmp
       "// Generated from ${file}; do not edit.\n#include <string_view>\n"
       "namespace clm3d::embedded {\nnamespace {\nconstexpr char ${symbol}Data[] = {${bytes} 0};\n}\n"
       "std::string_view ${symbol}() { return {${symbol}Data, ${byte_count}}; }\n}\n")
  configure_file(${out}.tmp ${out} COPYONLY)
  target_sources(${target} PRIVATE ${out})
endfunction()
