# Remove fortran modules provided by this target.
FILE(REMOVE
  "mod/fluid/fluid_flow.mod"
  "mod/fluid/FLUID_FLOW.mod"
  "CMakeFiles/udec_fluid.dir/fluid_flow.mod.stamp"
  )
