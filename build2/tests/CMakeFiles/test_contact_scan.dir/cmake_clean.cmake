file(REMOVE_RECURSE
  "CMakeFiles/test_contact_scan.dir/unit/test_contact_scan.f90.o"
  "test_contact_scan"
  "test_contact_scan.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_contact_scan.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
