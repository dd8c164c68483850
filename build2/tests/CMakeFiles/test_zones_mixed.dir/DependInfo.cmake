
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  "Fortran"
  )
# The set of files for implicit dependencies of each language:
set(CMAKE_DEPENDS_CHECK_Fortran
  "/work/wt-lead/tests/unit/test_zones_mixed.f90" "/work/wt-lead/build2/tests/CMakeFiles/test_zones_mixed.dir/unit/test_zones_mixed.f90.o"
  )
set(CMAKE_Fortran_COMPILER_ID "GNU")
set(CMAKE_Fortran_SUBMODULE_SEP "@")
set(CMAKE_Fortran_SUBMODULE_EXT ".smod")

# The include file search paths:
set(CMAKE_Fortran_TARGET_INCLUDE_PATH
  "mod/testing"
  "mod/model"
  "mod/core"
  "mod/commands"
  "mod/engine"
  "mod/contact"
  "mod/geometry"
  "mod/zones"
  "mod/structure"
  "mod/fluid"
  "mod/thermal"
  "mod/be"
  "mod/io"
  "/usr/include/hdf5/serial"
  "mod/plot"
  "/usr/include/editline"
  "/usr/include"
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  "/work/wt-lead/build2/tests/CMakeFiles/udec_testing_session.dir/DependInfo.cmake"
  "/work/wt-lead/build2/tests/CMakeFiles/udec_testing.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_commands.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_engine.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_zones.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_structure.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_fluid.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_thermal.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_be.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_io.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_plot.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_contact.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_geometry.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_model.dir/DependInfo.cmake"
  "/work/wt-lead/build2/CMakeFiles/udec_core.dir/DependInfo.cmake"
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "/work/wt-lead/build2/mod")
