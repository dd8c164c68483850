file(REMOVE_RECURSE
  "CMakeFiles/test_geometry_random.dir/unit/test_geometry_random.f90.o"
  "test_geometry_random"
  "test_geometry_random.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_geometry_random.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
