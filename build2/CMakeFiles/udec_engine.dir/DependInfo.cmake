
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  "Fortran"
  )
# The set of files for implicit dependencies of each language:
set(CMAKE_DEPENDS_CHECK_Fortran
  "/work/wt-lead/src/engine/engine_cycle.f90" "/work/wt-lead/build2/CMakeFiles/udec_engine.dir/src/engine/engine_cycle.f90.o"
  "/work/wt-lead/src/engine/engine_history.f90" "/work/wt-lead/build2/CMakeFiles/udec_engine.dir/src/engine/engine_history.f90.o"
  "/work/wt-lead/src/engine/engine_rigid.f90" "/work/wt-lead/build2/CMakeFiles/udec_engine.dir/src/engine/engine_rigid.f90.o"
  "/work/wt-lead/src/engine/engine_rigid_velocity.f90" "/work/wt-lead/build2/CMakeFiles/udec_engine.dir/src/engine/engine_rigid_velocity.f90.o"
  "/work/wt-lead/src/engine/engine_sdef.f90" "/work/wt-lead/build2/CMakeFiles/udec_engine.dir/src/engine/engine_sdef.f90.o"
  "/work/wt-lead/src/engine/engine_stages.f90" "/work/wt-lead/build2/CMakeFiles/udec_engine.dir/src/engine/engine_stages.f90.o"
  "/work/wt-lead/src/engine/engine_thermal.f90" "/work/wt-lead/build2/CMakeFiles/udec_engine.dir/src/engine/engine_thermal.f90.o"
  )
set(CMAKE_Fortran_COMPILER_ID "GNU")
set(CMAKE_Fortran_SUBMODULE_SEP "@")
set(CMAKE_Fortran_SUBMODULE_EXT ".smod")

# The include file search paths:
set(CMAKE_Fortran_TARGET_INCLUDE_PATH
  "mod/engine"
  "mod/contact"
  "mod/geometry"
  "mod/model"
  "mod/core"
  "mod/zones"
  "mod/structure"
  "mod/fluid"
  "mod/thermal"
  "mod/be"
  "/usr/include/editline"
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/wt-lead/build2/CMakeFiles/udec_contact.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_zones.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_structure.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_fluid.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_thermal.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_be.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_model.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_core.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_geometry.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "/work/wt-lead/build2/mod/engine")
