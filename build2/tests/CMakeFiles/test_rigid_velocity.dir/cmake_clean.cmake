file(REMOVE_RECURSE
  "CMakeFiles/test_rigid_velocity.dir/unit/test_rigid_velocity.f90.o"
  "test_rigid_velocity"
  "test_rigid_velocity.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_rigid_velocity.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
