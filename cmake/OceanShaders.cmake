# ocean_embed_shaders(OUT_VAR SHADERS file... [VARIANTS file:suffix:MACRO...] DEPENDS include...
#                     [INCLUDES dir...])
# Compiles each GLSL file of the calling module's shaders/ folder (the shaders live beside their
# owner: src/backends/vulkan/shaders, src/render/shaders) with glslc (stage from the extension) and embeds the SPIR-V
# as a word array (cmake/EmbedSpirv.cmake). The symbol is ocean_spv_<stem> for compute shaders
# and ocean_spv_<stem>_<ext> for graphics stages (ocean.vert → ocean_spv_ocean_vert). OUT_VAR
# receives the generated .cpp files. Each VARIANTS entry compiles a file once more with MACRO
# defined, as ocean_spv_<stem>_<ext>_<suffix> (ocean.vert:mv:OCEAN_MULTIVIEW → ocean_vert_mv).
# INCLUDES adds include directories after the shaders' own folder: a header another module owns
# (src/sim/far_noise.h, shared by C++, CUDA and GLSL) is included by its path from there
# ("sim/far_noise.h"), never by a relative "../" path. A DEPENDS entry is relative to shaders/
# unless absolute.
function(ocean_embed_shaders out_var)
  cmake_parse_arguments(ARG "" "" "SHADERS;VARIANTS;DEPENDS;INCLUDES" ${ARGN})
  set(shader_dir ${CMAKE_CURRENT_SOURCE_DIR}/shaders)
  set(generated)
  set(include_flags)
  foreach(dir ${ARG_INCLUDES})
    list(APPEND include_flags -I ${dir})
  endforeach()
  foreach(variant ${ARG_SHADERS} ${ARG_VARIANTS})
    string(REPLACE ":" ";" parts ${variant})
    list(GET parts 0 file)
    list(LENGTH parts fields)
    get_filename_component(stem ${file} NAME_WE)
    get_filename_component(ext ${file} LAST_EXT)
    string(SUBSTRING ${ext} 1 -1 ext)
    if(ext STREQUAL "comp")
      set(name ${stem})
    else()
      set(name ${stem}_${ext})
    endif()
    set(defines)
    if(fields EQUAL 3)
      list(GET parts 1 suffix)
      list(GET parts 2 macro)
      set(name ${name}_${suffix})
      set(defines -D${macro}=1)
    endif()
    set(spv ${CMAKE_CURRENT_BINARY_DIR}/shaders/${name}.spv)
    set(cpp ${CMAKE_CURRENT_BINARY_DIR}/shaders/${name}.spv.cpp)
    set(deps)
    foreach(dep ${ARG_DEPENDS})
      if(IS_ABSOLUTE ${dep})
        list(APPEND deps ${dep})
      else()
        list(APPEND deps ${shader_dir}/${dep})
      endif()
    endforeach()
    add_custom_command(
      OUTPUT ${cpp}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_CURRENT_BINARY_DIR}/shaders
      COMMAND ${OCEAN_GLSLC} --target-env=vulkan1.2 -O -Werror ${defines} -I ${shader_dir} ${include_flags}
              ${shader_dir}/${file} -o ${spv}
      COMMAND ${CMAKE_COMMAND} -DINPUT=${spv} -DOUTPUT=${cpp} -DNAME=ocean_spv_${name}
              -P ${PROJECT_SOURCE_DIR}/cmake/EmbedSpirv.cmake
      DEPENDS ${shader_dir}/${file} ${deps} ${PROJECT_SOURCE_DIR}/cmake/EmbedSpirv.cmake
      COMMENT "glslc ${file} → embedded SPIR-V"
      VERBATIM)
    list(APPEND generated ${cpp})
  endforeach()
  set(${out_var} ${generated} PARENT_SCOPE)
endfunction()
