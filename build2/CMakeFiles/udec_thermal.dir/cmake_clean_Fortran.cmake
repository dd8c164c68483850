# Remove fortran modules provided by this target.
FILE(REMOVE
  "mod/thermal/thermal_conduction.mod"
  "mod/thermal/THERMAL_CONDUCTION.mod"
  "CMakeFiles/udec_thermal.dir/thermal_conduction.mod.stamp"
  )
