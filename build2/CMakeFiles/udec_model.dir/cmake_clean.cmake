file(REMOVE_RECURSE
  "CMakeFiles/udec_model.dir/src/model/model_address.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_be.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_boundary.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_ffield.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_fluid.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_geometry.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_history.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_materials.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_mechanics.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_properties.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_reinforcement.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_state.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_structures.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_tables.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_thermal.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_zone_fields.f90.o"
  "CMakeFiles/udec_model.dir/src/model/model_zones.f90.o"
  "libudec_model.a"
  "libudec_model.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/udec_model.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
