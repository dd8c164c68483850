# Remove fortran modules provided by this target.
FILE(REMOVE
  "mod/structure/reinforce_generate.mod"
  "mod/structure/REINFORCE_GENERATE.mod"
  "CMakeFiles/udec_structure.dir/reinforce_generate.mod.stamp"

  "mod/structure/reinforce_mechanics.mod"
  "mod/structure/REINFORCE_MECHANICS.mod"
  "CMakeFiles/udec_structure.dir/reinforce_mechanics.mod.stamp"

  "mod/structure/structure_generate.mod"
  "mod/structure/STRUCTURE_GENERATE.mod"
  "CMakeFiles/udec_structure.dir/structure_generate.mod.stamp"

  "mod/structure/structure_mechanics.mod"
  "mod/structure/STRUCTURE_MECHANICS.mod"
  "CMakeFiles/udec_structure.dir/structure_mechanics.mod.stamp"

  "mod/structure/structure_models.mod"
  "mod/structure/STRUCTURE_MODELS.mod"
  "CMakeFiles/udec_structure.dir/structure_models.mod.stamp"
  )
