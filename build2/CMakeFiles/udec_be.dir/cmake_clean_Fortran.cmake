# Remove fortran modules provided by this target.
FILE(REMOVE
  "mod/be/be_far_field.mod"
  "mod/be/BE_FAR_FIELD.mod"
  "CMakeFiles/udec_be.dir/be_far_field.mod.stamp"

  "mod/be/be_halfplane.mod"
  "mod/be/BE_HALFPLANE.mod"
  "CMakeFiles/udec_be.dir/be_halfplane.mod.stamp"

  "mod/be/be_kelvin.mod"
  "mod/be/BE_KELVIN.mod"
  "CMakeFiles/udec_be.dir/be_kelvin.mod.stamp"

  "mod/be/be_lapack.mod"
  "mod/be/BE_LAPACK.mod"
  "CMakeFiles/udec_be.dir/be_lapack.mod.stamp"
  )
