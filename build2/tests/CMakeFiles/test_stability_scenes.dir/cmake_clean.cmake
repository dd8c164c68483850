file(REMOVE_RECURSE
  "CMakeFiles/test_stability_scenes.dir/unit/test_stability_scenes.f90.o"
  "test_stability_scenes"
  "test_stability_scenes.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_stability_scenes.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
