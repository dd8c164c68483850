file(REMOVE_RECURSE
  "CMakeFiles/udec_structure.dir/src/structure/reinforce_generate.f90.o"
  "CMakeFiles/udec_structure.dir/src/structure/reinforce_mechanics.f90.o"
  "CMakeFiles/udec_structure.dir/src/structure/structure_generate.f90.o"
  "CMakeFiles/udec_structure.dir/src/structure/structure_mechanics.f90.o"
  "CMakeFiles/udec_structure.dir/src/structure/structure_models.f90.o"
  "libudec_structure.a"
  "libudec_structure.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang Fortran)
  include(CMakeFiles/udec_structure.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
