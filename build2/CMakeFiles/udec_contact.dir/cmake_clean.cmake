file(REMOVE_RECURSE
  "CMakeFiles/udec_contact.dir/src/contact/contact_broadphase.f90.o"
  "CMakeFiles/udec_contact.dir/src/contact/contact_checks.f90.o"
  "CMakeFiles/udec_contact.dir/src/contact/contact_detection.f90.o"
  "CMakeFiles/udec_contact.dir/src/contact/contact_domains.f90.o"
  "CMakeFiles/udec_contact.dir/src/contact/contact_joint_law.f90.o"
  "CMakeFiles/udec_contact.dir/src/contact/contact_kinematics.f90.o"
  "CMakeFiles/udec_contact.dir/src/contact/contact_mechanics.f90.o"
  "CMakeFiles/udec_contact.dir/src/contact/contact_print.f90.o"
  "CMakeFiles/udec_contact.dir/src/contact/contact_refresh.f90.o"
  "CMakeFiles/udec_contact.dir/src/contact/contact_update.f90.o"
  "libudec_contact.a"
  "libudec_contact.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/udec_contact.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
