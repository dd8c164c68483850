# Remove fortran modules provided by this target.
FILE(REMOVE
  "mod/engine/engine_cycle.mod"
  "mod/engine/ENGINE_CYCLE.mod"
  "CMakeFiles/udec_engine.dir/engine_cycle.mod.stamp"

  "mod/engine/engine_history.mod"
  "mod/engine/ENGINE_HISTORY.mod"
  "CMakeFiles/udec_engine.dir/engine_history.mod.stamp"

  "mod/engine/engine_rigid.mod"
  "mod/engine/ENGINE_RIGID.mod"
  "CMakeFiles/udec_engine.dir/engine_rigid.mod.stamp"

  "mod/engine/engine_rigid_velocity.mod"
  "mod/engine/ENGINE_RIGID_VELOCITY.mod"
  "CMakeFiles/udec_engine.dir/engine_rigid_velocity.mod.stamp"

  "mod/engine/engine_sdef.mod"
  "mod/engine/ENGINE_SDEF.mod"
  "CMakeFiles/udec_engine.dir/engine_sdef.mod.stamp"

  "mod/engine/engine_stages.mod"
  "mod/engine/ENGINE_STAGES.mod"
  "CMakeFiles/udec_engine.dir/engine_stages.mod.stamp"

  "mod/engine/engine_thermal.mod"
  "mod/engine/ENGINE_THERMAL.mod"
  "CMakeFiles/udec_engine.dir/engine_thermal.mod.stamp"
  )
