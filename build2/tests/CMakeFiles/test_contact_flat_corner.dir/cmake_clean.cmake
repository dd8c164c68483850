file(REMOVE_RECURSE
  "CMakeFiles/test_contact_flat_corner.dir/unit/test_contact_flat_corner.f90.o"
  "test_contact_flat_corner"
  "test_contact_flat_corner.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_contact_flat_corner.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
