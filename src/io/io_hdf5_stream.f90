!> Field-by-field HDF5 access for the save file (the names live in io_schema).
!>
!> A `stream_t` either writes or reads. The schema walks the model once and
!> each call (`attr`, `text`, `names`, `field`) writes the value or reads it
!> back, so one list of calls per type defines both directions.
!>
!> Layout: groups for nested types, attributes for scalars and short fixed
!> arrays, one dataset per allocatable array holding its first n entries
!> (n along the last dimension) with an attribute `allocated_size` so that
!> the array comes back with the capacity it had (list growth then proceeds
!> exactly as it would have; -1 marks an unallocated array). Logicals are
!> stored as integers 0/1, strings as null-terminated C strings.
!>
!> Errors are sticky: after the first failure every call does nothing and
!> `message` says what went wrong and where (the HDF5 path). HDF5's own error
!> printing is switched off; every status goes through `check`.
module io_hdf5_stream
   use, intrinsic :: iso_c_binding, only: c_ptr, c_loc, c_char, c_null_char
   use, intrinsic :: iso_fortran_env, only: int8, int32, int64
   use core_kinds, only: wp, ip, l1
   use core_interrupt, only: interrupt_pending
   use core_files, only: c_string_text
   use hdf5, only: hid_t, hsize_t, size_t, h5open_f, h5eset_auto_f, &
                   h5fcreate_f, h5fopen_f, h5fclose_f, h5fis_hdf5_f, &
                   h5pset_fapl_core_f, &
                   H5F_ACC_TRUNC_F, H5F_ACC_RDONLY_F, H5F_CLOSE_STRONG_F, &
                   h5pcreate_f, H5P_FILE_ACCESS_F, H5P_DEFAULT_F, h5pset_fclose_degree_f, &
                   h5pclose_f, h5pset_libver_bounds_f, H5F_LIBVER_V110_F, &
                   H5P_DATASET_CREATE_F, h5pset_chunk_f, h5pset_fletcher32_f, &
                   H5P_FILE_CREATE_F, H5P_GROUP_CREATE_F, h5pset_obj_track_times_f, &
                   h5gcreate_f, h5gopen_f, h5gclose_f, h5lexists_f, &
                   h5screate_f, h5screate_simple_f, h5sclose_f, H5S_SCALAR_F, &
                   h5sget_simple_extent_ndims_f, h5sget_simple_extent_dims_f, &
                   h5sget_simple_extent_npoints_f, &
                   h5acreate_f, h5aopen_f, h5aclose_f, h5awrite_f, h5aread_f, h5aexists_f, &
                   h5aget_space_f, h5aget_type_f, &
                   h5dcreate_f, h5dopen_f, h5dclose_f, h5dwrite_f, h5dread_f, &
                   h5dget_space_f, h5dget_type_f, h5oopen_f, h5oclose_f, &
                   h5tcopy_f, h5tset_size_f, h5tget_size_f, h5tget_class_f, h5tclose_f, &
                   H5T_C_S1, H5T_NATIVE_DOUBLE, H5T_STD_I32LE, H5T_STD_I64LE, &
                   H5T_IEEE_F64LE, H5T_INTEGER_F, H5T_FLOAT_F, H5T_STRING_F, &
                   h5kind_to_type, H5_INTEGER_KIND
   implicit none
   private
   public :: stream_t, stream_write, stream_read

   integer, parameter :: stream_write = 1, stream_read = 2
   integer, parameter :: max_depth = 8
   character(len=*), parameter :: shape_name = 'allocated_size'
   !> Element types of attributes (exchange_attr).
   integer, parameter :: int32_kind = 1, int64_kind = 2, real64_kind = 3

   type :: stream_t
      integer :: mode = stream_write
      integer :: version = 0                   !< schema version of the file being read
      integer(hid_t) :: file = -1
      integer(hid_t) :: fapl = -1
      integer :: depth = 0
      integer(hid_t) :: group(0:max_depth) = -1
      character(len=:), allocatable :: path    !< current group, for messages
      character(len=:), allocatable :: message !< first error ('' while none)
      !> capacity of the last array read: a field newer than the file being
      !> read comes back zero-filled with the capacity of its list
      integer(int64) :: capacity = -1
   contains
      procedure :: failed => stream_failed
      procedure :: mode_is_read => stream_mode_is_read
      procedure :: fail => stream_fail
      procedure :: create => stream_create
      procedure :: open => stream_open
      procedure :: close => stream_close
      procedure :: begin_group => stream_begin_group
      procedure :: end_group => stream_end_group
      procedure :: has_attr => stream_has_attr
      procedure, private :: attr_scalar, attr_array
      generic :: attr => attr_scalar, attr_array
      procedure :: text => stream_text
      procedure :: names => stream_names
      procedure :: annotate => stream_annotate
      procedure, private :: field_real, field_int, field_logical, field_real2, field_logical2
      procedure, private :: field_int8, field_logical1
      generic :: field => field_real, field_int, field_logical, field_real2, field_logical2, &
         field_int8, field_logical1
   end type stream_t

contains

   logical function stream_failed(s)
      class(stream_t), intent(in) :: s
      stream_failed = .false.
      if (allocated(s%message)) stream_failed = len(s%message) > 0
   end function stream_failed

   logical function stream_mode_is_read(s)
      class(stream_t), intent(in) :: s
      stream_mode_is_read = s%mode == stream_read
   end function stream_mode_is_read

   !> Record the first error; later ones are consequences and are dropped.
   subroutine stream_fail(s, message)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: message
      if (s%failed()) return
      s%message = message
   end subroutine stream_fail

   !> Turn an HDF5 status into the stream's error.
   subroutine check(s, status, what)
      class(stream_t), intent(inout) :: s
      integer, intent(in) :: status
      character(len=*), intent(in) :: what
      if (status < 0) call s%fail('HDF5 could not '//what)
   end subroutine check

   function here(s, name) result(path)
      class(stream_t), intent(in) :: s
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: path
      if (s%path == '/') then
         path = '/'//name
      else
         path = s%path//'/'//name
      end if
   end function here

   !> True when reading a file older than the schema version `since` that
   !> brought a field: the field is absent and keeps its default.
   logical function skipped(s, since)
      class(stream_t), intent(in) :: s
      integer, intent(in), optional :: since
      skipped = .false.
      if (present(since)) skipped = s%mode == stream_read .and. s%version < since
   end function skipped

   !> HDF5 up, its error printing off (errors come back as messages).
   subroutine library_up(s)
      class(stream_t), intent(inout) :: s
      integer :: status
      call h5open_f(status)
      call check(s, status, 'initialise the library')
      if (s%failed()) return
      call h5eset_auto_f(0, status)
      call check(s, status, 'switch off its error printing')
      if (s%failed()) return
      ! closing the file closes whatever is still open in it (error paths)
      call h5pcreate_f(H5P_FILE_ACCESS_F, s%fapl, status)
      call check(s, status, 'create a file access list')
      if (s%failed()) return
      call h5pset_fclose_degree_f(s%fapl, H5F_CLOSE_STRONG_F, status)
      call check(s, status, 'set the file close degree')
      if (s%failed()) return
      ! the file format of HDF5 1.10 (readable by 1.10 and later): metadata,
      ! attributes included, is checksummed, so damage is detected; datasets
      ! of one chunk need no chunk index (small files)
      call h5pset_libver_bounds_f(s%fapl, H5F_LIBVER_V110_F, H5F_LIBVER_V110_F, status)
      call check(s, status, 'set the file format version')
   end subroutine library_up

   !> Create (truncate) `filename` for writing. HDF5's core driver builds the
   !> file in memory and writes it out when the file is closed: a failed
   !> write (disk full, file size limit) is then a clean error of `close`.
   !> (With the default driver, HDF5 1.10 crashes at program exit after a
   !> failed close; tests/scripts/save_restart.py checks this path.)
   subroutine stream_create(s, filename)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: filename
      integer :: status, ios
      integer(hid_t) :: fcpl
      s%mode = stream_write
      s%message = ''
      s%path = '/'
      s%depth = 0
      call library_up(s)
      if (s%failed()) return
      call h5pset_fapl_core_f(s%fapl, int(65536, size_t), .true., status)
      call check(s, status, 'select the in-memory file driver')
      if (s%failed()) return
      ! no creation times in the object headers: the same model saves to the
      ! same bytes (the thread-count test compares saved files byte for byte)
      call h5pcreate_f(H5P_FILE_CREATE_F, fcpl, status)
      call check(s, status, 'create a file creation list')
      if (s%failed()) return
      call h5pset_obj_track_times_f(fcpl, .false., status)
      call check(s, status, 'switch off object times')
      call h5fcreate_f(filename, H5F_ACC_TRUNC_F, s%file, status, &
                       creation_prp=fcpl, access_prp=s%fapl)
      call h5pclose_f(fcpl, ios)
      call check(s, status, 'create the file (is the disk full?)')
      if (s%failed()) return
      s%group(0) = s%file
   end subroutine stream_create

   !> Open an existing `filename` for reading.
   subroutine stream_open(s, filename)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: filename
      integer :: status
      logical :: is_hdf5
      s%mode = stream_read
      s%message = ''
      s%path = '/'
      s%depth = 0
      call library_up(s)
      if (s%failed()) return
      call h5fis_hdf5_f(filename, is_hdf5, status)
      if (status < 0 .or. .not. is_hdf5) then
         call s%fail('it is not an HDF5 file, so not a udec save file')
         return
      end if
      call h5fopen_f(filename, H5F_ACC_RDONLY_F, s%file, status, access_prp=s%fapl)
      if (status < 0) then
         call s%fail('HDF5 cannot open it (the file is truncated or damaged)')
         return
      end if
      s%group(0) = s%file
   end subroutine stream_open

   !> Close everything that is open; a failure to close a written file (disk
   !> full at the final flush) becomes the stream's error.
   subroutine stream_close(s)
      class(stream_t), intent(inout) :: s
      integer :: status
      do while (s%depth > 0)
         call h5gclose_f(s%group(s%depth), status)
         s%depth = s%depth - 1
      end do
      if (s%file >= 0) then
         call h5fclose_f(s%file, status)
         call check(s, status, 'close the file (is the disk full?)')
         s%file = -1
      end if
      if (s%fapl >= 0) then
         call h5pclose_f(s%fapl, status)
         s%fapl = -1
      end if
   end subroutine stream_close

   subroutine stream_begin_group(s, name)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      integer :: status
      logical :: exists
      integer(hid_t) :: id, gcpl
      integer :: ios
      if (s%failed()) return
      if (s%depth >= max_depth) then
         call s%fail('internal error: groups nested too deeply at '//here(s, name))
         return
      end if
      if (s%mode == stream_write) then
         ! Ctrl-C / SIGTERM: a SAVE stops between groups; io_save_model
         ! removes the temporary and leaves any older file as it was
         if (interrupt_pending()) then
            call s%fail('interrupted (Ctrl-C or SIGTERM) before it was complete; '// &
                        'nothing was written')
            return
         end if
         call h5pcreate_f(H5P_GROUP_CREATE_F, gcpl, status)
         call check(s, status, 'create a group creation list for '//here(s, name))
         if (s%failed()) return
         call h5pset_obj_track_times_f(gcpl, .false., status)
         call h5gcreate_f(s%group(s%depth), name, id, status, gcpl_id=gcpl)
         call h5pclose_f(gcpl, ios)
         call check(s, status, 'create group '//here(s, name))
      else
         call h5lexists_f(s%group(s%depth), name, exists, status)
         call check(s, status, 'look for group '//here(s, name))
         if (s%failed()) return
         if (.not. exists) then
            call s%fail('group '//here(s, name)//' is missing')
            return
         end if
         call h5gopen_f(s%group(s%depth), name, id, status)
         call check(s, status, 'open group '//here(s, name))
      end if
      if (s%failed()) return
      s%path = here(s, name)
      s%depth = s%depth + 1
      s%group(s%depth) = id
   end subroutine stream_begin_group

   subroutine stream_end_group(s)
      class(stream_t), intent(inout) :: s
      integer :: status, k
      if (s%failed()) return
      call h5gclose_f(s%group(s%depth), status)
      call check(s, status, 'close group '//s%path)
      s%depth = s%depth - 1
      k = index(s%path, '/', back=.true.)
      s%path = s%path(1:max(1, k - 1))
   end subroutine stream_end_group

   !> Whether the current group has attribute `name` (reading).
   logical function stream_has_attr(s, name) result(exists)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      integer :: status
      exists = .false.
      if (s%failed()) return
      call h5aexists_f(s%group(s%depth), name, exists, status)
      call check(s, status, 'look for attribute '//here(s, name))
   end function stream_has_attr

   ! ---- attributes -----------------------------------------------------------

   !> Write attribute `name` on object `loc`: `n` elements (0: a scalar).
   subroutine put_attr(s, loc, where, name, file_type, mem_type, n, ptr)
      class(stream_t), intent(inout) :: s
      integer(hid_t), intent(in) :: loc, file_type, mem_type
      character(len=*), intent(in) :: where, name
      integer, intent(in) :: n
      type(c_ptr), intent(in) :: ptr
      integer(hid_t) :: space, attr
      integer :: status
      if (s%failed()) return
      if (n == 0) then
         call h5screate_f(H5S_SCALAR_F, space, status)
      else
         call h5screate_simple_f(1, [int(n, hsize_t)], space, status)
      end if
      call check(s, status, 'create a dataspace for '//where//'@'//name)
      if (s%failed()) return
      call h5acreate_f(loc, name, file_type, space, attr, status)
      call check(s, status, 'create attribute '//where//'@'//name)
      if (.not. s%failed()) then
         call h5awrite_f(attr, mem_type, ptr, status)
         call check(s, status, 'write attribute '//where//'@'//name)
         call h5aclose_f(attr, status)
      end if
      call h5sclose_f(space, status)
   end subroutine put_attr

   !> Open attribute `name` of `loc` and check its class and element count
   !> (n = 0: a scalar; n < 0: 1 to -n elements). Returns attr = -1 after a
   !> failure, and the element count in `found`.
   subroutine open_attr(s, loc, where, name, class, n, attr, found)
      class(stream_t), intent(inout) :: s
      integer(hid_t), intent(in) :: loc
      character(len=*), intent(in) :: where, name
      integer, intent(in) :: class, n
      integer(hid_t), intent(out) :: attr
      integer, intent(out), optional :: found
      integer(hid_t) :: space, dtype
      integer(hsize_t) :: npoints
      integer :: status, found_class
      logical :: exists, size_ok
      attr = -1
      npoints = 0
      if (present(found)) found = 0
      if (s%failed()) return
      call h5aexists_f(loc, name, exists, status)
      call check(s, status, 'look for attribute '//where//'@'//name)
      if (s%failed()) return
      if (.not. exists) then
         call s%fail('attribute '//where//'@'//name//' is missing')
         return
      end if
      call h5aopen_f(loc, name, attr, status)
      call check(s, status, 'open attribute '//where//'@'//name)
      if (s%failed()) return
      call h5aget_space_f(attr, space, status)
      call check(s, status, 'read the dataspace of '//where//'@'//name)
      if (.not. s%failed()) then
         call h5sget_simple_extent_npoints_f(space, npoints, status)
         call check(s, status, 'count the elements of '//where//'@'//name)
         call h5sclose_f(space, status)
      end if
      if (.not. s%failed()) then
         call h5aget_type_f(attr, dtype, status)
         call check(s, status, 'read the type of '//where//'@'//name)
      end if
      if (.not. s%failed()) then
         call h5tget_class_f(dtype, found_class, status)
         call check(s, status, 'read the type class of '//where//'@'//name)
         call h5tclose_f(dtype, status)
         if (.not. s%failed()) then
            if (n >= 0) then
               size_ok = npoints == max(n, 1)
            else
               size_ok = npoints >= 1 .and. npoints <= -n
            end if
            if (.not. size_ok .or. found_class /= class) &
               call s%fail('attribute '//where//'@'//name//' has the wrong type or size')
            if (present(found)) found = int(npoints)
         end if
      end if
      if (s%failed()) then
         call h5aclose_f(attr, status)
         attr = -1
      end if
   end subroutine open_attr

   subroutine get_attr(s, loc, where, name, class, mem_type, n, ptr)
      class(stream_t), intent(inout) :: s
      integer(hid_t), intent(in) :: loc, mem_type
      character(len=*), intent(in) :: where, name
      integer, intent(in) :: class, n
      type(c_ptr), intent(in) :: ptr
      integer(hid_t) :: attr
      integer :: status
      type(c_ptr) :: target
      call open_attr(s, loc, where, name, class, n, attr)
      if (s%failed()) return
      target = ptr     ! HDF5 declares the buffer argument intent(inout)
      call h5aread_f(attr, mem_type, target, status)
      call check(s, status, 'read attribute '//where//'@'//name)
      call h5aclose_f(attr, status)
   end subroutine get_attr

   !> Write (or read) attribute `name` of the current group from `ptr`: `n`
   !> elements (0: a scalar) of the element type `kind` (int32_kind, ..).
   subroutine exchange_attr(s, name, kind, n, ptr)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      integer, intent(in) :: kind, n
      type(c_ptr), intent(in) :: ptr
      integer(hid_t) :: file_type, mem_type
      integer :: class
      select case (kind)
      case (int32_kind)
         file_type = H5T_STD_I32LE
         class = H5T_INTEGER_F
         mem_type = int32_type()
      case (int64_kind)
         file_type = H5T_STD_I64LE
         class = H5T_INTEGER_F
         mem_type = int64_type()
      case default
         file_type = H5T_IEEE_F64LE
         class = H5T_FLOAT_F
         mem_type = H5T_NATIVE_DOUBLE
      end select
      if (s%mode == stream_write) then
         call put_attr(s, s%group(s%depth), s%path, name, file_type, mem_type, n, ptr)
      else
         call get_attr(s, s%group(s%depth), s%path, name, class, mem_type, n, ptr)
      end if
   end subroutine exchange_attr

   !> True while a read goes well: the value read may be stored.
   logical function read_ok(s)
      class(stream_t), intent(in) :: s
      read_ok = s%mode == stream_read .and. .not. s%failed()
   end function read_ok

   !> A scalar attribute: a 32- or 64-bit integer, a real, or a logical
   !> (as integer 0/1).
   subroutine attr_scalar(s, name, value, since)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      class(*), intent(inout) :: value
      integer, intent(in), optional :: since
      integer(int32), target :: i4
      integer(int64), target :: i8v
      real(wp), target :: r
      if (s%failed() .or. skipped(s, since)) return
      select type (value)
      type is (integer(int32))
         i4 = value
         call exchange_attr(s, name, int32_kind, 0, c_loc(i4))
         if (read_ok(s)) value = i4
      type is (logical)
         i4 = merge(1_int32, 0_int32, value)
         call exchange_attr(s, name, int32_kind, 0, c_loc(i4))
         if (.not. read_ok(s)) return
         if (i4 /= 0 .and. i4 /= 1) then
            call s%fail('attribute '//here(s, name)//' should be 0 or 1')
            return
         end if
         value = i4 == 1
      type is (integer(int64))
         i8v = value
         call exchange_attr(s, name, int64_kind, 0, c_loc(i8v))
         if (read_ok(s)) value = i8v
      type is (real(wp))
         r = value
         call exchange_attr(s, name, real64_kind, 0, c_loc(r))
         if (read_ok(s)) value = r
      class default
         call s%fail('internal error: attribute '//here(s, name)//' has a type the save file does not hold')
      end select
   end subroutine attr_scalar

   !> A short fixed-size array as one attribute: integers (counters) or
   !> reals (gravity(2), jregion_x(4)).
   subroutine attr_array(s, name, value, since)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      class(*), intent(inout) :: value(:)
      integer, intent(in), optional :: since
      integer(int32), allocatable, target :: iv(:)
      real(wp), allocatable, target :: rv(:)
      if (s%failed() .or. skipped(s, since)) return
      select type (value)
      type is (integer(int32))
         iv = value
         call exchange_attr(s, name, int32_kind, size(iv), c_loc(iv))
         if (read_ok(s)) value = iv
      type is (real(wp))
         rv = value
         call exchange_attr(s, name, real64_kind, size(rv), c_loc(rv))
         if (read_ok(s)) value = rv
      class default
         call s%fail('internal error: attribute '//here(s, name)//' has a type the save file does not hold')
      end select
   end subroutine attr_array

   !> A deferred-length string (kept exactly, trailing blanks included).
   subroutine stream_text(s, name, value, since)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      character(len=:), allocatable, intent(inout) :: value
      integer, intent(in), optional :: since
      character(kind=c_char), allocatable, target :: buf(:)
      integer :: i
      if (s%failed() .or. skipped(s, since)) return
      if (s%mode == stream_write) then
         if (.not. allocated(value)) value = ''
         allocate (buf(len(value) + 1))
         do i = 1, len(value)
            buf(i) = value(i:i)
         end do
         buf(len(value) + 1) = c_null_char
         call put_strings(s, name, buf, len(value) + 1, 0)
      else
         call get_strings(s, name, 0, buf, i)
         if (s%failed()) return
         value = c_string_text(buf)
      end if
   end subroutine stream_text

   !> A constant list of names written for the reader's benefit (what the
   !> rows of a table mean). Such lists only grow at the end: reading checks
   !> that the file's list is the start of this version's list.
   subroutine stream_names(s, name, list)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      character(len=*), intent(in) :: list(:)
      character(kind=c_char), allocatable, target :: buf(:)
      integer :: i, j, width, n, count
      if (s%failed()) return
      n = size(list)
      width = len(list) + 1
      if (s%mode == stream_write) then
         allocate (buf(width*n))
         buf = c_null_char
         do i = 1, n
            do j = 1, len_trim(list(i))
               buf((i - 1)*width + j) = list(i)(j:j)
            end do
         end do
         call put_strings(s, name, buf, width, n)
      else
         call get_strings(s, name, -n, buf, width, count)
         if (s%failed()) return
         do i = 1, count
            if (c_string_text(buf((i - 1)*width + 1:i*width)) /= trim(list(i))) then
               call s%fail('attribute '//here(s, name)//' lists other names than this '// &
                           'version of udec uses')
               return
            end if
         end do
      end if
   end subroutine stream_names

   !> Writing: attribute `name` = `text` on the object (dataset or group) at
   !> absolute `path`, when the file has it (a physics a model does not use
   !> writes no group). What a file's integer codes mean (io_schema): the
   !> file then explains itself to h5dump or h5py.
   subroutine stream_annotate(s, path, name, text)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: path, name, text
      character(kind=c_char), allocatable, target :: buf(:)
      integer(hid_t) :: obj, dtype
      integer :: status, i, k
      logical :: exists
      if (s%failed() .or. s%mode /= stream_write) return
      ! every component of the path must exist before the next is asked
      k = 1
      do
         i = index(path(k + 1:), '/')
         if (i == 0) then
            call h5lexists_f(s%file, path, exists, status)
         else
            call h5lexists_f(s%file, path(1:k + i - 1), exists, status)
         end if
         if (status < 0 .or. .not. exists) return
         if (i == 0) exit
         k = k + i
      end do
      call h5oopen_f(s%file, path, obj, status)
      call check(s, status, 'open '//path//' to annotate it')
      if (s%failed()) return
      allocate (buf(len(text) + 1))
      do i = 1, len(text)
         buf(i) = text(i:i)
      end do
      buf(len(text) + 1) = c_null_char
      call h5tcopy_f(H5T_C_S1, dtype, status)
      call check(s, status, 'create a string type for '//path//'@'//name)
      if (.not. s%failed()) then
         call h5tset_size_f(dtype, int(len(text) + 1, size_t), status)
         call put_attr(s, obj, path, name, dtype, dtype, 0, c_loc(buf))
         call h5tclose_f(dtype, status)
      end if
      call h5oclose_f(obj, status)
   end subroutine stream_annotate

   !> `n` strings (0: one scalar string) of `width` bytes each, null-padded.
   subroutine put_strings(s, name, buf, width, n)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      character(kind=c_char), intent(in), target :: buf(:)
      integer, intent(in) :: width, n
      integer(hid_t) :: dtype
      integer :: status
      call h5tcopy_f(H5T_C_S1, dtype, status)
      call check(s, status, 'create a string type for '//here(s, name))
      if (s%failed()) return
      call h5tset_size_f(dtype, int(width, size_t), status)
      call check(s, status, 'size a string type for '//here(s, name))
      call put_attr(s, s%group(s%depth), s%path, name, dtype, dtype, n, c_loc(buf))
      call h5tclose_f(dtype, status)
   end subroutine put_strings

   !> Read `n` strings (0: one scalar string; < 0: between 1 and -n of them,
   !> their number returned in `count`).
   subroutine get_strings(s, name, n, buf, width, count)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      integer, intent(in) :: n
      character(kind=c_char), allocatable, target, intent(out) :: buf(:)
      integer, intent(out) :: width
      integer, intent(out), optional :: count
      integer(hid_t) :: attr, dtype
      integer(size_t) :: size
      integer :: status, found
      type(c_ptr) :: target
      width = 0
      call open_attr(s, s%group(s%depth), s%path, name, H5T_STRING_F, n, attr, found)
      if (present(count)) count = found
      if (s%failed()) return
      call h5aget_type_f(attr, dtype, status)
      call check(s, status, 'read the type of '//here(s, name))
      if (s%failed()) then
         call h5aclose_f(attr, status)
         return
      end if
      call h5tget_size_f(dtype, size, status)
      call check(s, status, 'read the string size of '//here(s, name))
      if (.not. s%failed()) then
         width = int(size)
         allocate (buf(width*max(found, 1)))
         target = c_loc(buf)
         call h5aread_f(attr, dtype, target, status)
         call check(s, status, 'read attribute '//here(s, name))
      end if
      call h5tclose_f(dtype, status)
      call h5aclose_f(attr, status)
   end subroutine get_strings

   ! ---- datasets -------------------------------------------------------------

   !> Write dataset `name` of shape `dims` with its `allocated_size` attribute.
   subroutine put_array(s, name, file_type, mem_type, dims, shape, ptr)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      integer(hid_t), intent(in) :: file_type, mem_type
      integer(hsize_t), intent(in) :: dims(:)
      integer(int64), intent(in) :: shape(:)
      type(c_ptr), intent(in) :: ptr
      integer(int64), allocatable, target :: shape_buf(:)
      integer(hid_t) :: space, dset, dcpl
      integer :: status
      if (s%failed()) return
      call h5screate_simple_f(size(dims), dims, space, status)
      call check(s, status, 'create a dataspace for '//here(s, name))
      if (s%failed()) return
      ! data checksummed too (Fletcher-32 needs a chunked layout: one chunk)
      call h5pcreate_f(H5P_DATASET_CREATE_F, dcpl, status)
      call check(s, status, 'create a dataset creation list for '//here(s, name))
      if (.not. s%failed()) call h5pset_obj_track_times_f(dcpl, .false., status)
      if (product(dims) > 0 .and. .not. s%failed()) then
         call h5pset_chunk_f(dcpl, size(dims), dims, status)
         call check(s, status, 'set the chunk of '//here(s, name))
         call h5pset_fletcher32_f(dcpl, status)
         call check(s, status, 'set the checksum of '//here(s, name))
      end if
      if (s%failed()) then
         call h5sclose_f(space, status)
         return
      end if
      call h5dcreate_f(s%group(s%depth), name, file_type, space, dset, status, dcpl_id=dcpl)
      call check(s, status, 'create dataset '//here(s, name))
      call h5pclose_f(dcpl, status)
      if (.not. s%failed()) then
         if (product(dims) > 0) then
            call h5dwrite_f(dset, mem_type, ptr, status)
            call check(s, status, 'write dataset '//here(s, name))
         end if
         shape_buf = shape
         call put_attr(s, dset, here(s, name), shape_name, H5T_STD_I64LE, int64_type(), &
                       size(shape_buf), c_loc(shape_buf))
         call h5dclose_f(dset, status)
      end if
      call h5sclose_f(space, status)
   end subroutine put_array

   !> Open dataset `name` (rank `rank`, element class `class`), check that it
   !> holds `n` entries along its last dimension and that its allocated size
   !> can hold them; return its dims and allocated shape.
   subroutine array_shape(s, name, rank, class, n, dims, shape)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      integer, intent(in) :: rank, class
      integer(ip), intent(in) :: n
      integer(hsize_t), intent(out) :: dims(rank)
      integer(int64), intent(out) :: shape(rank)
      integer(int64), target :: shape_buf(rank)
      integer(hsize_t) :: maxdims(rank)
      integer(hid_t) :: dset, space, dtype
      integer :: status, found_rank, found_class
      logical :: exists
      character(len=64) :: detail
      dims = 0
      shape = -1
      found_rank = -1
      found_class = -1
      if (s%failed()) return
      call h5lexists_f(s%group(s%depth), name, exists, status)
      call check(s, status, 'look for dataset '//here(s, name))
      if (s%failed()) return
      if (.not. exists) then
         call s%fail('dataset '//here(s, name)//' is missing')
         return
      end if
      call h5dopen_f(s%group(s%depth), name, dset, status)
      call check(s, status, 'open dataset '//here(s, name))
      if (s%failed()) return
      call h5dget_space_f(dset, space, status)
      call check(s, status, 'read the dataspace of '//here(s, name))
      if (.not. s%failed()) then
         call h5sget_simple_extent_ndims_f(space, found_rank, status)
         call check(s, status, 'read the rank of '//here(s, name))
         if (.not. s%failed() .and. found_rank == rank) then
            call h5sget_simple_extent_dims_f(space, dims, maxdims, status)
            call check(s, status, 'read the size of '//here(s, name))
         else if (.not. s%failed()) then
            call s%fail('dataset '//here(s, name)//' has the wrong rank')
         end if
         call h5sclose_f(space, status)
      end if
      if (.not. s%failed()) then
         call h5dget_type_f(dset, dtype, status)
         call check(s, status, 'read the type of '//here(s, name))
         if (.not. s%failed()) then
            call h5tget_class_f(dtype, found_class, status)
            call check(s, status, 'read the type class of '//here(s, name))
            call h5tclose_f(dtype, status)
            if (.not. s%failed() .and. found_class /= class) &
               call s%fail('dataset '//here(s, name)//' has the wrong type')
         end if
      end if
      if (.not. s%failed()) then
         call get_attr(s, dset, here(s, name), shape_name, H5T_INTEGER_F, int64_type(), &
                       rank, c_loc(shape_buf))
         shape = shape_buf
      end if
      call h5dclose_f(dset, status)
      if (s%failed()) return
      ! the entries present must fit the allocation, and agree with n
      if (n < 0 .or. dims(rank) /= int(n, hsize_t) .or. &
          (shape(rank) >= 0 .and. shape(rank) < n) .or. (shape(rank) < 0 .and. n > 0) .or. &
          any(shape < -1)) then
         write (detail, '(a,i0,a,i0)') ' (count ', n, ', entries ', dims(rank)
         call s%fail('dataset '//here(s, name)//' does not match its list'//trim(detail)//')')
         return
      end if
      if (rank == 2) then
         if (shape(rank) >= 0 .and. int(dims(1), int64) /= shape(1)) then
            call s%fail('dataset '//here(s, name)//' does not match its allocated size')
            return
         end if
      end if
      s%capacity = shape(rank)
   end subroutine array_shape

   subroutine get_array(s, name, mem_type, ptr)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      integer(hid_t), intent(in) :: mem_type
      type(c_ptr), intent(in) :: ptr
      integer(hid_t) :: dset
      integer :: status
      type(c_ptr) :: target
      if (s%failed()) return
      call h5dopen_f(s%group(s%depth), name, dset, status)
      call check(s, status, 'open dataset '//here(s, name))
      if (s%failed()) return
      target = ptr     ! HDF5 declares the buffer argument intent(inout)
      call h5dread_f(dset, mem_type, target, status)
      call check(s, status, 'read dataset '//here(s, name)//' (the file is truncated or damaged)')
      call h5dclose_f(dset, status)
   end subroutine get_array

   subroutine field_real(s, name, a, n, since)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      real(wp), allocatable, intent(inout) :: a(:)
      integer(ip), intent(in) :: n
      integer, intent(in), optional :: since
      real(wp), allocatable, target :: buf(:)
      real(wp), parameter :: zero = 0.0_wp
      integer(hid_t) :: file_type, mem_type
      integer :: class
      integer(hsize_t) :: dims(1)
      integer(int64) :: shape(1)
      if (s%failed()) return
      file_type = H5T_IEEE_F64LE
      mem_type = H5T_NATIVE_DOUBLE
      class = H5T_FLOAT_F
      include 'io_hdf5_field.inc'
   end subroutine field_real

   subroutine field_int(s, name, a, n, since)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      integer(int32), allocatable, intent(inout) :: a(:)
      integer(ip), intent(in) :: n
      integer, intent(in), optional :: since
      integer(int32), allocatable, target :: buf(:)
      integer(int32), parameter :: zero = 0_int32
      integer(hid_t) :: file_type, mem_type
      integer :: class
      integer(hsize_t) :: dims(1)
      integer(int64) :: shape(1)
      if (s%failed()) return
      file_type = H5T_STD_I32LE
      mem_type = int32_type()
      class = H5T_INTEGER_F
      include 'io_hdf5_field.inc'
   end subroutine field_int

   !> Logicals as the integers 0/1 of field_int.
   subroutine field_logical(s, name, a, n, since)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      logical, allocatable, intent(inout) :: a(:)
      integer(ip), intent(in) :: n
      integer, intent(in), optional :: since
      integer(int32), allocatable :: v(:)
      logical :: kept, dropped
      if (s%failed()) return
      if (s%mode == stream_write .and. allocated(a)) then
         allocate (v(size(a)), source=0_int32)
         if (n > 0) v(1:n) = merge(1_int32, 0_int32, a(1:n))
      end if
      call narrow_field(s, name, v, n, since, 0, 1, 'only 0 and 1', kept, dropped)
      if ((kept .or. dropped) .and. allocated(a)) deallocate (a)
      if (kept) then
         allocate (a(size(v)))
         a = v == 1
      end if
   end subroutine field_logical

   !> One-byte logicals as field_logical writes and reads default ones (the
   !> file's layout does not depend on the kind the list keeps).
   subroutine field_logical1(s, name, a, n, since)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      logical(l1), allocatable, intent(inout) :: a(:)
      integer(ip), intent(in) :: n
      integer, intent(in), optional :: since
      logical, allocatable :: t(:)
      if (s%failed()) return
      if (allocated(a)) t = logical(a)
      call s%field_logical(name, t, n, since)
      if (allocated(t)) then
         a = logical(t, l1)
      else if (allocated(a)) then
         deallocate (a)
      end if
   end subroutine field_logical1

   !> One-byte codes as the 32-bit integers of field_int: the file's layout
   !> does not depend on how narrow a list keeps them; read back, a value
   !> outside -128 .. 127 is an error.
   subroutine field_int8(s, name, a, n, since)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      integer(int8), allocatable, intent(inout) :: a(:)
      integer(ip), intent(in) :: n
      integer, intent(in), optional :: since
      integer(int32), allocatable :: v(:)
      logical :: kept, dropped
      if (s%failed()) return
      if (s%mode == stream_write .and. allocated(a)) then
         allocate (v(size(a)), source=0_int32)
         if (n > 0) v(1:n) = int(a(1:n), int32)
      end if
      call narrow_field(s, name, v, n, since, -128, 127, 'codes from -128 to 127', kept, dropped)
      if ((kept .or. dropped) .and. allocated(a)) deallocate (a)
      if (kept) then
         allocate (a(size(v)))
         a = int(v, int8)
      end if
   end subroutine field_int8

   !> The 32-bit image v of a narrower list (field_logical, field_int8)
   !> through field_int. Read back: `kept` when v holds the list (entries
   !> beyond n are zero) and every value lies in lo .. hi, else the stream
   !> fails saying the dataset should hold `what`; `dropped` when the file
   !> has no list (not allocated when saved), so the caller's goes too.
   subroutine narrow_field(s, name, v, n, since, lo, hi, what, kept, dropped)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name, what
      integer(int32), allocatable, intent(inout) :: v(:)
      integer(ip), intent(in) :: n
      integer, intent(in), optional :: since
      integer, intent(in) :: lo, hi
      logical, intent(out) :: kept, dropped
      kept = .false.
      dropped = .false.
      call s%field(name, v, n, since)
      if (.not. read_ok(s)) return
      if (allocated(v)) then
         if (any(v < lo .or. v > hi)) then
            call s%fail('dataset '//here(s, name)//' should hold '//what)
            return
         end if
         kept = .true.
      else
         dropped = .not. skipped(s, since)
      end if
   end subroutine narrow_field

   !> Rank 2: the first `n` columns a(:, 1:n).
   subroutine field_real2(s, name, a, n)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      real(wp), allocatable, intent(inout) :: a(:, :)
      integer(ip), intent(in) :: n
      real(wp), allocatable, target :: buf(:, :)
      integer(hsize_t) :: dims(2)
      integer(int64) :: shape(2)
      if (s%failed()) return
      if (s%mode == stream_write) then
         shape = -1
         if (allocated(a)) shape = shape_of(size(a, 1), size(a, 2))
         allocate (buf(max(shape(1), 0_int64), n))
         if (n > 0) buf = a(:, 1:n)
         call put_array(s, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &
                        int([size(buf, 1), size(buf, 2)], hsize_t), shape, c_loc(buf))
      else
         call array_shape(s, name, 2, H5T_FLOAT_F, n, dims, shape)
         if (s%failed()) return
         allocate (buf(dims(1), dims(2)))
         if (size(buf) > 0) call get_array(s, name, H5T_NATIVE_DOUBLE, c_loc(buf))
         if (s%failed()) return
         if (allocated(a)) deallocate (a)
         if (shape(2) < 0) return
         allocate (a(shape(1), shape(2)), source=0.0_wp)
         a(:, 1:n) = buf
      end if
   end subroutine field_real2

   subroutine field_logical2(s, name, a, n)
      class(stream_t), intent(inout) :: s
      character(len=*), intent(in) :: name
      logical, allocatable, intent(inout) :: a(:, :)
      integer(ip), intent(in) :: n
      integer(int32), allocatable, target :: buf(:, :)
      integer(hsize_t) :: dims(2)
      integer(int64) :: shape(2)
      if (s%failed()) return
      if (s%mode == stream_write) then
         shape = -1
         if (allocated(a)) shape = shape_of(size(a, 1), size(a, 2))
         allocate (buf(max(shape(1), 0_int64), n))
         if (n > 0) buf = merge(1_int32, 0_int32, a(:, 1:n))
         call put_array(s, name, H5T_STD_I32LE, int32_type(), &
                        int([size(buf, 1), size(buf, 2)], hsize_t), shape, c_loc(buf))
      else
         call array_shape(s, name, 2, H5T_INTEGER_F, n, dims, shape)
         if (s%failed()) return
         allocate (buf(dims(1), dims(2)))
         if (size(buf) > 0) call get_array(s, name, int32_type(), c_loc(buf))
         if (s%failed()) return
         if (any(buf /= 0 .and. buf /= 1)) then
            call s%fail('dataset '//here(s, name)//' should hold only 0 and 1')
            return
         end if
         if (allocated(a)) deallocate (a)
         if (shape(2) < 0) return
         allocate (a(shape(1), shape(2)), source=.false.)
         a(:, 1:n) = buf == 1
      end if
   end subroutine field_logical2

   pure function shape_of(n1, n2) result(shape)
      integer, intent(in) :: n1, n2
      integer(int64) :: shape(2)
      shape = [int(n1, int64), int(n2, int64)]
   end function shape_of

   integer(hid_t) function int32_type() result(t)
      t = h5kind_to_type(int32, H5_INTEGER_KIND)
   end function int32_type

   integer(hid_t) function int64_type() result(t)
      t = h5kind_to_type(int64, H5_INTEGER_KIND)
   end function int64_type

end module io_hdf5_stream
