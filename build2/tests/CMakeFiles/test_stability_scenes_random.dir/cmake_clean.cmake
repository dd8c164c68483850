file(REMOVE_RECURSE
  "CMakeFiles/test_stability_scenes_random.dir/unit/test_stability_scenes_random.f90.o"
  "test_stability_scenes_random"
  "test_stability_scenes_random.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_stability_scenes_random.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
