file(REMOVE_RECURSE
  "CMakeFiles/test_fluid_commands.dir/unit/test_fluid_commands.f90.o"
  "test_fluid_commands"
  "test_fluid_commands.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/test_fluid_commands.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
