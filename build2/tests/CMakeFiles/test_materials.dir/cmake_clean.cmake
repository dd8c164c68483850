file(REMOVE_RECURSE
  "CMakeFiles/test_materials.dir/unit/test_materials.f90.o"
  "test_materials"
  "test_materials.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_materials.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
