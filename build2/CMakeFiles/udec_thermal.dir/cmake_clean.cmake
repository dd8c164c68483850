file(REMOVE_RECURSE
  "CMakeFiles/udec_thermal.dir/src/thermal/thermal_conduction.f90.o"
  "libudec_thermal.a"
  "libudec_thermal.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/udec_thermal.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
