file(REMOVE_RECURSE
  "CMakeFiles/udec_engine.dir/src/engine/engine_cycle.f90.o"
  "CMakeFiles/udec_engine.dir/src/engine/engine_history.f90.o"
  "CMakeFiles/udec_engine.dir/src/engine/engine_rigid.f90.o"
  "CMakeFiles/udec_engine.dir/src/engine/engine_rigid_velocity.f90.o"
  "CMakeFiles/udec_engine.dir/src/engine/engine_sdef.f90.o"
  "CMakeFiles/udec_engine.dir/src/engine/engine_stages.f90.o"
  "CMakeFiles/udec_engine.dir/src/engine/engine_thermal.f90.o"
  "libudec_engine.a"
  "libudec_engine.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/udec_engine.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
