# Remove fortran modules provided by this target.
FILE(REMOVE
  "mod/geometry/geometry_blocks.mod"
  "mod/geometry/GEOMETRY_BLOCKS.mod"
  "CMakeFiles/udec_geometry.dir/geometry_blocks.mod.stamp"

  "mod/geometry/geometry_cutting.mod"
  "mod/geometry/GEOMETRY_CUTTING.mod"
  "CMakeFiles/udec_geometry.dir/geometry_cutting.mod.stamp"

  "mod/geometry/geometry_joint_sets.mod"
  "mod/geometry/GEOMETRY_JOINT_SETS.mod"
  "CMakeFiles/udec_geometry.dir/geometry_joint_sets.mod.stamp"

  "mod/geometry/geometry_polygon.mod"
  "mod/geometry/GEOMETRY_POLYGON.mod"
  "CMakeFiles/udec_geometry.dir/geometry_polygon.mod.stamp"
  )
