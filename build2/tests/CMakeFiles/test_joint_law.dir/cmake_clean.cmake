file(REMOVE_RECURSE
  "CMakeFiles/test_joint_law.dir/unit/test_joint_law.f90.o"
  "test_joint_law"
  "test_joint_law.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_joint_law.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
