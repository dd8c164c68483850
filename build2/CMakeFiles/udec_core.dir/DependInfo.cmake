
# Consider dependencies only in project.
set(CMAKE_DEPENDS_IN_PROJECT_ONLY OFF)

# The set of languages for which implicit dependencies are needed:
set(CMAKE_DEPENDS_LANGUAGES
  "Fortran"
  )
# The set of files for implicit dependencies of each language:
set(CMAKE_DEPENDS_CHECK_Fortran
  "/work/wt-lead/build2/generated/core_version.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/generated/core_version.f90.o"
  "/work/wt-lead/src/core/core_arrays.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/src/core/core_arrays.f90.o"
  "/work/wt-lead/src/core/core_constants.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/src/core/core_constants.f90.o"
  "/work/wt-lead/src/core/core_error.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/src/core/core_error.f90.o"
  "/work/wt-lead/src/core/core_files.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/src/core/core_files.f90.o"
  "/work/wt-lead/src/core/core_forces.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/src/core/core_forces.f90.o"
  "/work/wt-lead/src/core/core_interrupt.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/src/core/core_interrupt.f90.o"
  "/work/wt-lead/src/core/core_kinds.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/src/core/core_kinds.f90.o"
  "/work/wt-lead/src/core/core_limits.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/src/core/core_limits.f90.o"
  "/work/wt-lead/src/core/core_lineedit.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/src/core/core_lineedit.f90.o"
  "/work/wt-lead/src/core/core_output.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/src/core/core_output.f90.o"
  "/work/wt-lead/src/core/core_progress.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/src/core/core_progress.f90.o"
  "/work/wt-lead/src/core/core_range.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/src/core/core_range.f90.o"
  "/work/wt-lead/src/core/core_sort.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/src/core/core_sort.f90.o"
  "/work/wt-lead/src/core/core_strings.f90" "/work/wt-lead/build2/CMakeFiles/udec_core.dir/src/core/core_strings.f90.o"
  )
set(CMAKE_Fortran_COMPILER_ID "GNU")
set(CMAKE_Fortran_SUBMODULE_SEP "@")
set(CMAKE_Fortran_SUBMODULE_EXT ".smod")

# The include file search paths:
set(CMAKE_Fortran_TARGET_INCLUDE_PATH
  "mod/core"
  "/usr/include/editline"
  )

# The set of dependency files which are needed:
set(CMAKE_DEPENDS_DEPENDENCY_FILES
  "/work/wt-lead/src/core/core_lineedit.c" "CMakeFiles/udec_core.dir/src/core/core_lineedit.c.o" "gcc" "CMakeFiles/udec_core.dir/src/core/core_lineedit.c.o.d"
  "/work/wt-lead/src/core/core_signals.c" "CMakeFiles/udec_core.dir/src/core/core_signals.c.o" "gcc" "CMakeFiles/udec_core.dir/src/core/core_signals.c.o.d"
  "/work/wt-lead/src/core/core_stat.c" "CMakeFiles/udec_core.dir/src/core/core_stat.c.o" "gcc" "CMakeFiles/udec_core.dir/src/core/core_stat.c.o.d"
  )

# Targets to which this target links.
set(CMAKE_TARGET_LINKED_INFO_FILES
  )

# Fortran module output directory.
set(CMAKE_Fortran_TARGET_MODULE_DIR "/work/wt-lead/build2/mod/core")
