file(REMOVE_RECURSE
  "CMakeFiles/test_rigid_mechanics.dir/unit/test_rigid_mechanics.f90.o"
  "test_rigid_mechanics"
  "test_rigid_mechanics.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_rigid_mechanics.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
