# embed_shaders(<target> <dir> [headers...]): compiles every file in <dir>, and
# the headers named after it (a library's GLSL, e.g. NanoVDB's PNanoVDB.h), into
# <target> as text, reachable by file name through contexts/gl/shader_sources.h.
# The files are read again whenever one changes.
function(embed_shaders target dir)
  file(GLOB shader_files CONFIGURE_DEPENDS "${dir}/*.vert" "${dir}/*.geom" "${dir}/*.frag"
       "${dir}/*.comp" "${dir}/*.glsl")
  list(APPEND shader_files ${ARGN})
  set(out "${CMAKE_CURRENT_BINARY_DIR}/embedded_shaders.cpp")
  add_custom_command(
    OUTPUT "${out}"
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DFILES="${shader_files}"
            -P "${PROJECT_SOURCE_DIR}/cmake/WriteEmbeddedShaders.cmake"
    DEPENDS ${shader_files} "${PROJECT_SOURCE_DIR}/cmake/WriteEmbeddedShaders.cmake"
    COMMENT "Embedding shaders from ${dir}")
  target_sources(${target} PRIVATE "${out}")
endfunction()
