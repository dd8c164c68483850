file(REMOVE_RECURSE
  "CMakeFiles/test_stability_rigid.dir/unit/test_stability_rigid.f90.o"
  "test_stability_rigid"
  "test_stability_rigid.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_stability_rigid.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
