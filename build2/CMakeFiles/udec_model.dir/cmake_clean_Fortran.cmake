# Remove fortran modules provided by this target.
FILE(REMOVE
  "mod/model/model_address.mod"
  "mod/model/MODEL_ADDRESS.mod"
  "CMakeFiles/udec_model.dir/model_address.mod.stamp"

  "mod/model/model_be.mod"
  "mod/model/MODEL_BE.mod"
  "CMakeFiles/udec_model.dir/model_be.mod.stamp"

  "mod/model/model_boundary.mod"
  "mod/model/MODEL_BOUNDARY.mod"
  "CMakeFiles/udec_model.dir/model_boundary.mod.stamp"

  "mod/model/model_ffield.mod"
  "mod/model/MODEL_FFIELD.mod"
  "CMakeFiles/udec_model.dir/model_ffield.mod.stamp"

  "mod/model/model_fluid.mod"
  "mod/model/MODEL_FLUID.mod"
  "CMakeFiles/udec_model.dir/model_fluid.mod.stamp"

  "mod/model/model_geometry.mod"
  "mod/model/MODEL_GEOMETRY.mod"
  "CMakeFiles/udec_model.dir/model_geometry.mod.stamp"

  "mod/model/model_history.mod"
  "mod/model/MODEL_HISTORY.mod"
  "CMakeFiles/udec_model.dir/model_history.mod.stamp"

  "mod/model/model_materials.mod"
  "mod/model/MODEL_MATERIALS.mod"
  "CMakeFiles/udec_model.dir/model_materials.mod.stamp"

  "mod/model/model_mechanics.mod"
  "mod/model/MODEL_MECHANICS.mod"
  "CMakeFiles/udec_model.dir/model_mechanics.mod.stamp"

  "mod/model/model_properties.mod"
  "mod/model/MODEL_PROPERTIES.mod"
  "CMakeFiles/udec_model.dir/model_properties.mod.stamp"

  "mod/model/model_reinforcement.mod"
  "mod/model/MODEL_REINFORCEMENT.mod"
  "CMakeFiles/udec_model.dir/model_reinforcement.mod.stamp"

  "mod/model/model_state.mod"
  "mod/model/MODEL_STATE.mod"
  "CMakeFiles/udec_model.dir/model_state.mod.stamp"

  "mod/model/model_structures.mod"
  "mod/model/MODEL_STRUCTURES.mod"
  "CMakeFiles/udec_model.dir/model_structures.mod.stamp"

  "mod/model/model_tables.mod"
  "mod/model/MODEL_TABLES.mod"
  "CMakeFiles/udec_model.dir/model_tables.mod.stamp"

  "mod/model/model_thermal.mod"
  "mod/model/MODEL_THERMAL.mod"
  "CMakeFiles/udec_model.dir/model_thermal.mod.stamp"

  "mod/model/model_zone_fields.mod"
  "mod/model/MODEL_ZONE_FIELDS.mod"
  "CMakeFiles/udec_model.dir/model_zone_fields.mod.stamp"

  "mod/model/model_zones.mod"
  "mod/model/MODEL_ZONES.mod"
  "CMakeFiles/udec_model.dir/model_zones.mod.stamp"
  )
