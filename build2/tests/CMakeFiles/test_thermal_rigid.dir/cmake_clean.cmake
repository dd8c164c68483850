file(REMOVE_RECURSE
  "CMakeFiles/test_thermal_rigid.dir/unit/test_thermal_rigid.f90.o"
  "test_thermal_rigid"
  "test_thermal_rigid.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_thermal_rigid.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
