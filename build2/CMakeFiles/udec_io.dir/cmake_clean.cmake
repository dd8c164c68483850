file(REMOVE_RECURSE
  "CMakeFiles/udec_io.dir/src/io/io_hdf5_library.f90.o"
  "CMakeFiles/udec_io.dir/src/io/io_hdf5_stream.f90.o"
  "CMakeFiles/udec_io.dir/src/io/io_posix.f90.o"
  "CMakeFiles/udec_io.dir/src/io/io_schema.f90.o"
  "CMakeFiles/udec_io.dir/src/io/io_signals.c.o"
  "CMakeFiles/udec_io.dir/src/io/io_signals.c.o.d"
  "libudec_io.a"
  "libudec_io.pdb"
)

# Per-language clean rules from dependency scanning.
foreach(lang C Fortran)
  include(CMakeFiles/udec_io.dir/cmake_clean_${lang}.cmake OPTIONAL)
endforeach()
