# Remove fortran modules provided by this target.
FILE(REMOVE
  "mod/contact/contact_broadphase.mod"
  "mod/contact/CONTACT_BROADPHASE.mod"
  "CMakeFiles/udec_contact.dir/contact_broadphase.mod.stamp"

  "mod/contact/contact_checks.mod"
  "mod/contact/CONTACT_CHECKS.mod"
  "CMakeFiles/udec_contact.dir/contact_checks.mod.stamp"

  "mod/contact/contact_detection.mod"
  "mod/contact/CONTACT_DETECTION.mod"
  "CMakeFiles/udec_contact.dir/contact_detection.mod.stamp"

  "mod/contact/contact_domains.mod"
  "mod/contact/CONTACT_DOMAINS.mod"
  "CMakeFiles/udec_contact.dir/contact_domains.mod.stamp"

  "mod/contact/contact_joint_law.mod"
  "mod/contact/CONTACT_JOINT_LAW.mod"
  "CMakeFiles/udec_contact.dir/contact_joint_law.mod.stamp"

  "mod/contact/contact_kinematics.mod"
  "mod/contact/CONTACT_KINEMATICS.mod"
  "CMakeFiles/udec_contact.dir/contact_kinematics.mod.stamp"

  "mod/contact/contact_mechanics.mod"
  "mod/contact/CONTACT_MECHANICS.mod"
  "CMakeFiles/udec_contact.dir/contact_mechanics.mod.stamp"

  "mod/contact/contact_print.mod"
  "mod/contact/CONTACT_PRINT.mod"
  "CMakeFiles/udec_contact.dir/contact_print.mod.stamp"

  "mod/contact/contact_refresh.mod"
  "mod/contact/CONTACT_REFRESH.mod"
  "CMakeFiles/udec_contact.dir/contact_refresh.mod.stamp"

  "mod/contact/contact_update.mod"
  "mod/contact/CONTACT_UPDATE.mod"
  "CMakeFiles/udec_contact.dir/contact_update.mod.stamp"
  )
