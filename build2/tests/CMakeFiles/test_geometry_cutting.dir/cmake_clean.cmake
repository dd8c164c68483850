file(REMOVE_RECURSE
  "CMakeFiles/test_geometry_cutting.dir/unit/test_geometry_cutting.f90.o"
  "test_geometry_cutting"
  "test_geometry_cutting.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_geometry_cutting.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
