# The interface between the playground's page and the WebAssembly engine: a stamp taken from
# the engine's bindings (src/wasm/engine.cpp) and the writers of the JSON they answer with
# (src/inspection), which the engine carries as its first line and the program expects, so that
# `camcov playground --engine` refuses any other file (an older engine, another script) instead
# of writing a page that draws nothing. Included by the program's build and by the engine's own
# (src/wasm), so both compute the one stamp.
function(camcov_engine_interface out_line)
  set(root ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/..)
  set(text "")
  foreach(file src/wasm/engine.cpp src/inspection/inspection_json.cpp
               src/inspection/explanation_json.cpp)
    file(READ ${root}/${file} content)
    string(APPEND text "${content}")
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${root}/${file})
  endforeach()
  string(SHA256 hash "${text}")
  string(SUBSTRING ${hash} 0 16 hash)
  set(${out_line} "// camcov engine interface ${hash}" PARENT_SCOPE)
endfunction()
