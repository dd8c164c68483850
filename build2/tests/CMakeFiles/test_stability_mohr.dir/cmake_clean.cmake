file(REMOVE_RECURSE
  "CMakeFiles/test_stability_mohr.dir/unit/test_stability_mohr.f90.o"
  "test_stability_mohr"
  "test_stability_mohr.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_stability_mohr.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
