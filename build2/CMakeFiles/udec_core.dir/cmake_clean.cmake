file(REMOVE_RECURSE
  "CMakeFiles/udec_core.dir/generated/core_version.f90.o"
  "CMakeFiles/udec_core.dir/src/core/core_arrays.f90.o"
  "CMakeFiles/udec_core.dir/src/core/core_constants.f90.o"
  "CMakeFiles/udec_core.dir/src/core/core_error.f90.o"
  "CMakeFiles/udec_core.dir/src/core/core_files.f90.o"
  "CMakeFiles/udec_core.dir/src/core/core_forces.f90.o"
  "CMakeFiles/udec_core.dir/src/core/core_interrupt.f90.o"
  "CMakeFiles/udec_core.dir/src/core/core_kinds.f90.o"
  "CMakeFiles/udec_core.dir/src/core/core_limits.f90.o"
  "CMakeFiles/udec_core.dir/src/core/core_lineedit.c.o"
  "CMakeFiles/udec_core.dir/src/core/core_lineedit.c.o.d"
  "CMakeFiles/udec_core.dir/src/core/core_lineedit.f90.o"
  "CMakeFiles/udec_core.dir/src/core/core_output.f90.o"
  "CMakeFiles/udec_core.dir/src/core/core_progress.f90.o"
  "CMakeFiles/udec_core.dir/src/core/core_range.f90.o"
  "CMakeFiles/udec_core.dir/src/core/core_signals.c.o"
  "CMakeFiles/udec_core.dir/src/core/core_signals.c.o.d"
  "CMakeFiles/udec_core.dir/src/core/core_sort.f90.o"
  "CMakeFiles/udec_core.dir/src/core/core_stat.c.o"
  "CMakeFiles/udec_core.dir/src/core/core_stat.c.o.d"
  "CMakeFiles/udec_core.dir/src/core/core_strings.f90.o"
  "libudec_core.a"
  "libudec_core.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C Fortran)
  include(CMakeFiles/udec_core.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
