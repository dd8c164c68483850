# udec_add_layer(<name> <folder> [DEPENDS targets...] [EXTRA_SOURCES files...])
# Builds static library udec_<name> from every Fortran/C source in <folder>.
# A folder with no sources yet (a physics still to come) produces no target.
function(udec_add_layer name folder)
  cmake_parse_arguments(L "" "" "DEPENDS;EXTRA_SOURCES" ${ARGN})
  file(GLOB_RECURSE srcs CONFIGURE_DEPENDS
       ${CMAKE_SOURCE_DIR}/${folder}/*.f90 ${CMAKE_SOURCE_DIR}/${folder}/*.F90
       ${CMAKE_SOURCE_DIR}/${folder}/*.c)
  list(APPEND srcs ${L_EXTRA_SOURCES})
  if(NOT srcs)
    add_library(udec_${name} INTERFACE)
    foreach(dep ${L_DEPENDS})
      target_link_libraries(udec_${name} INTERFACE ${dep})
    endforeach()
    return()
  endif()
  add_library(udec_${name} STATIC ${srcs})
  set_target_properties(udec_${name} PROPERTIES
      Fortran_MODULE_DIRECTORY ${CMAKE_BINARY_DIR}/mod/${name})
  target_include_directories(udec_${name} PUBLIC ${CMAKE_BINARY_DIR}/mod/${name})
  foreach(dep ${L_DEPENDS})
    target_link_libraries(udec_${name} PUBLIC ${dep})
  endforeach()
endfunction()
