!> The OSMesa library (and the libLLVM its software rasteriser maps) is
!> opened only when the first PNG is made (src/plot/plot_gl.c, issue 23):
!> not mapped in this process before, mapped after; when it cannot be loaded
!> (UDEC_OSMESA_LIBRARY naming a missing file) COPY to a .png fails with a
!> message naming COPY, the file and the names tried, writes nothing, and
!> the session goes on: the next COPY, the variable unset, makes the PNG.
program test_plot_lazy_load
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
   use testing, only: check, check_equal, testing_finish, delete_file
   use testing_session, only: session_run, lines_contain, session_new_quiet
   use commands_session, only: session_t
   use plot_backends, only: osmesa_loaded
   implicit none
   interface
      function setenv(name, value, overwrite) bind(c, name='setenv')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: name(*), value(*)
         integer(c_int), value :: overwrite
         integer(c_int) :: setenv
      end function setenv
      function unsetenv(name) bind(c, name='unsetenv')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: name(*)
         integer(c_int) :: unsetenv
      end function unsetenv
   end interface
   type(session_t) :: s
   character(len=200), allocatable :: lines(:)
   character(len=*), parameter :: png = 'test_plot_lazy_load_out.png'
   integer :: errors, unit, ios
   logical :: exists

   call session_new_quiet(s)
   call check(.not. mapped('libOSMesa'), 'OSMesa not mapped at start')
   call check(.not. mapped('libLLVM'), 'libLLVM not mapped at start')
   call check(.not. osmesa_loaded(), 'OSMesa not loaded at start')
   call session_run(s, 'BLOCK 0 0 0 10 10 10 10 0', lines)
   call session_run(s, 'CRACK 0 5 10 5', lines)
   call session_run(s, 'PLOT BLOCKS', lines)
   call session_run(s, 'COPY test_plot_lazy_load_out.ps', lines)
   call check(.not. mapped('libOSMesa'), 'a PostScript plot does not load OSMesa')

   ! the library cannot be loaded: a clear error, nothing written, no change
   call check_equal(int(setenv('UDEC_OSMESA_LIBRARY'//c_null_char, &
                               'udec-no-such-dir/libOSMesa.so'//c_null_char, 1_c_int)), 0, 'setenv')
   errors = s%nerrors
   call delete_file(png)
   call session_run(s, 'COPY '//png, lines)
   call check_equal(s%nerrors, errors + 1, 'COPY .png without OSMesa is an error')
   call check(lines_contain(lines, 'COPY: cannot make the PNG file'), 'error names COPY and the PNG')
   call check(lines_contain(lines, 'could not be loaded'), 'error says the library could not be loaded')
   call check(lines_contain(lines, 'udec-no-such-dir/libOSMesa.so'), 'error names what was tried')
   inquire (file=png, exist=exists)
   call check(.not. exists, 'no PNG file written')
   call check(.not. osmesa_loaded(), 'still not loaded')

   ! the library found: the PNG is made, and OSMesa is now mapped
   call check_equal(int(unsetenv('UDEC_OSMESA_LIBRARY'//c_null_char)), 0, 'unsetenv')
   call session_run(s, 'COPY '//png, lines)
   call check_equal(s%nerrors, errors + 1, 'COPY .png succeeds once OSMesa loads')
   inquire (file=png, exist=exists)
   call check(exists, 'PNG file written')
   call check(osmesa_loaded(), 'OSMesa loaded after the first PNG')
   call check(mapped('libOSMesa'), 'OSMesa mapped after the first PNG')
   ! a second PNG reuses the library
   call session_run(s, 'COPY '//png, lines)
   call check_equal(s%nerrors, errors + 1, 'a second PNG')
   call delete_file(png)
   call delete_file('test_plot_lazy_load_out.ps')
   call testing_finish()

contains

   !> A file whose name contains `name` is mapped into this process.
   logical function mapped(name)
      character(len=*), intent(in) :: name
      character(len=512) :: line
      mapped = .false.
      open (newunit=unit, file='/proc/self/maps', action='read', status='old', iostat=ios)
      if (ios /= 0) return
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (index(line, name) > 0) mapped = .true.
      end do
      close (unit)
   end function mapped

end program test_plot_lazy_load
