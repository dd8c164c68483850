# Remove fortran modules provided by this target.
FILE(REMOVE
  "mod/zones/zones_boundary.mod"
  "mod/zones/ZONES_BOUNDARY.mod"
  "CMakeFiles/udec_zones.dir/zones_boundary.mod.stamp"

  "mod/zones/zones_boundary_setup.mod"
  "mod/zones/ZONES_BOUNDARY_SETUP.mod"
  "CMakeFiles/udec_zones.dir/zones_boundary_setup.mod.stamp"

  "mod/zones/zones_ffield.mod"
  "mod/zones/ZONES_FFIELD.mod"
  "CMakeFiles/udec_zones.dir/zones_ffield.mod.stamp"

  "mod/zones/zones_generate.mod"
  "mod/zones/ZONES_GENERATE.mod"
  "CMakeFiles/udec_zones.dir/zones_generate.mod.stamp"

  "mod/zones/zones_mechanics.mod"
  "mod/zones/ZONES_MECHANICS.mod"
  "CMakeFiles/udec_zones.dir/zones_mechanics.mod.stamp"

  "mod/zones/zones_mesh.mod"
  "mod/zones/ZONES_MESH.mod"
  "CMakeFiles/udec_zones.dir/zones_mesh.mod.stamp"

  "mod/zones/zones_mesh_base.mod"
  "mod/zones/ZONES_MESH_BASE.mod"
  "CMakeFiles/udec_zones.dir/zones_mesh_base.mod.stamp"

  "mod/zones/zones_mesh_manual.mod"
  "mod/zones/ZONES_MESH_MANUAL.mod"
  "CMakeFiles/udec_zones.dir/zones_mesh_manual.mod.stamp"

  "mod/zones/zones_mesh_quad.mod"
  "mod/zones/ZONES_MESH_QUAD.mod"
  "CMakeFiles/udec_zones.dir/zones_mesh_quad.mod.stamp"

  "mod/zones/zones_mixed.mod"
  "mod/zones/ZONES_MIXED.mod"
  "CMakeFiles/udec_zones.dir/zones_mixed.mod.stamp"

  "mod/zones/zones_models.mod"
  "mod/zones/ZONES_MODELS.mod"
  "CMakeFiles/udec_zones.dir/zones_models.mod.stamp"

  "mod/zones/zones_pressure.mod"
  "mod/zones/ZONES_PRESSURE.mod"
  "CMakeFiles/udec_zones.dir/zones_pressure.mod.stamp"

  "mod/zones/zones_refinement.mod"
  "mod/zones/ZONES_REFINEMENT.mod"
  "CMakeFiles/udec_zones.dir/zones_refinement.mod.stamp"

  "mod/zones/zones_triangulation.mod"
  "mod/zones/ZONES_TRIANGULATION.mod"
  "CMakeFiles/udec_zones.dir/zones_triangulation.mod.stamp"

  "mod/zones/zones_viscous.mod"
  "mod/zones/ZONES_VISCOUS.mod"
  "CMakeFiles/udec_zones.dir/zones_viscous.mod.stamp"
  )
