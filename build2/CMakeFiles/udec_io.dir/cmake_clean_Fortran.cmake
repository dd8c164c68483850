# Remove fortran modules provided by this target.
FILE(REMOVE
  "mod/io/io_hdf5_library.mod"
  "mod/io/IO_HDF5_LIBRARY.mod"
  "CMakeFiles/udec_io.dir/io_hdf5_library.mod.stamp"

  "mod/io/io_hdf5_stream.mod"
  "mod/io/IO_HDF5_STREAM.mod"
  "CMakeFiles/udec_io.dir/io_hdf5_stream.mod.stamp"

  "mod/io/io_posix.mod"
  "mod/io/IO_POSIX.mod"
  "CMakeFiles/udec_io.dir/io_posix.mod.stamp"

  "mod/io/io_schema.mod"
  "mod/io/IO_SCHEMA.mod"
  "CMakeFiles/udec_io.dir/io_schema.mod.stamp"
  )
