file(REMOVE_RECURSE
  "CMakeFiles/test_geometry_contacts.dir/unit/test_geometry_contacts.f90.o"
  "test_geometry_contacts"
  "test_geometry_contacts.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_geometry_contacts.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
