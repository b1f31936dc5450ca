# The interface between the playground's page and the WebAssembly engine: a stamp taken from
# the engine's bindings (src/wasm/engine.cpp), which the engine carries as its first line and
# the program expects, so that `camcov playground --engine` refuses any other file (an older
# engine, another script) instead of writing a page that draws nothing. Included by the
# program's build and by the engine's own (src/wasm), so both compute the one stamp.
function(camcov_engine_interface bindings out_line)
  file(SHA256 ${bindings} hash)
  string(SUBSTRING ${hash} 0 16 hash)
  set(${out_line} "// camcov engine interface ${hash}" PARENT_SCOPE)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${bindings})
endfunction()
