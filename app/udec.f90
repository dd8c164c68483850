!> udec: the command-line program. Decides the run mode (manual Sections 2.1,
!> 2.2, 4.3, 4.4), sets up the output and runs the interpreter. This is the only
!> place that ends the program with a status.
!>
!>   udec               batch on ./DATA if present, otherwise interactive (UDEC> )
!>   udec FILE          batch on FILE
!>   udec --check FILE  parse FILE only; report every syntax error
!>   udec --commands-md print the command reference (docs/commands.md)
!>   udec --man         print the manual page (docs/udec.1)
program udec
   use, intrinsic :: iso_c_binding, only: c_int
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use core_error, only: error_t
   use core_version, only: udec_version, udec_license
   use commands_session, only: session_t, session_init, session_push_file, &
                               session_push_stdin, session_run, session_finish
   use commands_help, only: help_markdown, help_man
   use be_lapack, only: lapack_version_string
   use io_hdf5_library, only: hdf5_version_string
   use io_posix, only: ignore_file_size_signal
   use core_files, only: check_output_file
   use core_interrupt, only: interrupt_install
   use core_progress, only: stdout_is_terminal
   use plot_backends, only: png_version_string, osmesa_available
   implicit none

   interface
      subroutine c_exit(status) bind(c, name='exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit
   end interface

   type(session_t) :: session
   type(error_t), allocatable :: error
   character(len=:), allocatable :: arg, file
   character(len=:), allocatable :: check_files(:)
   integer :: i, nargs, ncheck, out_unit, ios, status
   logical :: exists, check_mode, commands_md, man_page

   call ignore_file_size_signal()
   nargs = command_argument_count()
   file = ''
   check_mode = .false.
   commands_md = .false.
   man_page = .false.
   ncheck = 0
   allocate (character(len=4096) :: check_files(max(nargs, 1)))
   i = 0
   do while (i < nargs)
      i = i + 1
      arg = get_arg(i)
      select case (arg)
      case ('-h', '--help')
         call print_help()
         call finish(0)
      case ('-V', '--version')
         call print_version()
         call finish(0)
      case ('--check')
         check_mode = .true.
      case ('--commands-md')
         commands_md = .true.
      case ('--man')
         man_page = .true.
      case default
         if (arg(1:min(1, len(arg))) == '-' .and. len(arg) > 1) then
            write (error_unit, '(a)') "udec: unknown option '"//arg//"' (try udec --help)"
            call finish(2)
         end if
         if (check_mode) then
            ncheck = ncheck + 1
            check_files(ncheck) = arg
         else if (len(file) == 0) then
            file = arg
         else
            write (error_unit, '(a)') 'udec: only one input FILE may be given (try udec --help)'
            call finish(2)
         end if
      end select
   end do
   ! (the program ends by exit(): valgrind counted the last argument as lost)
   if (allocated(arg)) deallocate (arg)

   call session_init(session, error)
   if (allocated(error)) then
      write (error_unit, '(a)') 'udec: internal error: '//error%message
      call finish(3)
   end if

   if (commands_md) then
      call help_markdown(session%registry, session%grammar, output_unit)
      call finish(0)
   end if
   if (man_page) then
      call help_man(session%registry, session%grammar, output_unit)
      call finish(0)
   end if

   if (check_mode) then
      if (ncheck == 0) then
         write (error_unit, '(a)') 'udec: --check needs at least one FILE'
         call finish(2)
      end if
      call run_check()
   end if

   if (len(file) == 0) then
      inquire (file='DATA', exist=exists)
      if (exists) file = 'DATA'
   end if

   ! on a terminal CYCLE, SOLVE and RUN show a progress line instead of rows
   session%out%tty = stdout_is_terminal()
   ! Ctrl-C / SIGTERM end a running CYCLE instead of the program
   call interrupt_install(interactive=len(file) == 0)
   call session%out%line('UDEC (udec '//udec_version//') - distinct element code for jointed rock')
   if (len(file) > 0) then
      session%batch = .true.
      ! OUT must be a regular file (or new): a folder, device or FIFO named OUT
      ! is left alone and the run goes on with the screen only
      call check_output_file('', 'OUT', error)
      ios = 1
      if (.not. allocated(error)) open (newunit=out_unit, file='OUT', status='replace', &
                                        action='write', iostat=ios)
      if (ios == 0) then
         call session%out%add_unit(out_unit)
      else
         if (allocated(error)) then
            write (error_unit, '(a)') 'udec: warning: '//error%message
            deallocate (error)
         else
            write (error_unit, '(a)') 'udec: warning: cannot write the output file OUT'
         end if
         out_unit = -1
      end if
      call session_push_file(session, file, error)
      if (allocated(error)) then
         call session%out%line('*** Error: '//error%message)
         call close_and_finish(1)
      end if
   else
      call session_push_stdin(session)
      out_unit = -1
   end if

   inquire (file='UDEC.INI', exist=exists)
   if (exists) then
      call session_push_file(session, 'UDEC.INI', error, defaults=.true.)
      if (allocated(error)) call session%out%line('*** Warning: '//error%message)
   end if

   call session_run(session)
   status = session%exit_status
   call close_and_finish(status)

contains

   function get_arg(k) result(text)
      integer, intent(in) :: k
      character(len=:), allocatable :: text
      integer :: n
      call get_command_argument(k, length=n)
      allocate (character(len=n) :: text)
      if (n > 0) call get_command_argument(k, text)
   end function get_arg

   !> Parse-only mode: every file is checked; status 1 if any error.
   subroutine run_check()
      integer :: k, total
      total = 0
      session%check_only = .true.
      session%batch = .true.
      do k = 1, ncheck
         session%stopped = .false.
         session%nerrors = 0
         call session_push_file(session, trim(check_files(k)), error)
         if (allocated(error)) then
            call session%out%line('*** Error: '//error%message)
            total = total + 1
            cycle
         end if
         call session_run(session)
         if (session%nerrors == 0) then
            call session%out%line(trim(check_files(k))//': ok')
         else
            total = total + session%nerrors
         end if
      end do
      call session_finish(session)
      call finish(merge(1, 0, total > 0))
   end subroutine run_check

   subroutine close_and_finish(code)
      integer, intent(in) :: code
      call session_finish(session)
      if (out_unit /= -1) then
         call session%out%remove_unit(out_unit)
         close (out_unit)
      end if
      call finish(code)
   end subroutine close_and_finish

   subroutine finish(code)
      integer, intent(in) :: code
      flush (output_unit)
      flush (error_unit)
      call c_exit(int(code, c_int))
   end subroutine finish

   subroutine print_help()
      write (output_unit, '(a)') &
         'Usage: udec [FILE]', &
         '       udec --check FILE...', &
         '       udec --commands-md | --man', &
         '', &
         'udec reimplements UDEC, the two-dimensional distinct element code for', &
         'jointed rock masses, reading the command language of the UDEC manual.', &
         '', &
         '  udec            run ./DATA in batch mode if it exists, otherwise start', &
         '                  the interactive UDEC> prompt', &
         '  udec FILE       run FILE in batch mode (output to the screen and to OUT)', &
         '  --check FILE..  parse the files only and report every syntax error', &
         '  --commands-md   print the command reference (docs/commands.md) and stop', &
         '  --man           print the manual page (docs/udec.1, man(7) roff) and stop', &
         '  -h, --help      show this help', &
         '  -V, --version   show the version and the linked libraries', &
         '', &
         'UDEC.INI in the working folder is read first when present.', &
         'Ctrl-C stops a running CYCLE or RUN at the end of a step (twice within', &
         '2 s: quit). Exit status: 128 + signal after SIGINT or SIGTERM in a', &
         'batch run, 0 after STOP or end of input, 1 after an input error in', &
         'batch mode (or any error with --check), 2 for bad command-line usage.'
   end subroutine print_help

   subroutine print_version()
      character(len=400) :: why
      write (output_unit, '(a)') 'udec '//udec_version
      write (output_unit, '(a)') '  License '//udec_license//' (see LICENSE): copyright the udec authors'
      write (output_unit, '(a)') '  HDF5    '//hdf5_version_string()
      write (output_unit, '(a)') '  LAPACK  '//lapack_version_string()
      write (output_unit, '(a)') '  libpng  '//png_version_string()
      if (osmesa_available(why)) then
         write (output_unit, '(a)') '  OSMesa  off-screen context available (loaded when a PNG is made)'
      else if (len_trim(why) > 0) then
         write (output_unit, '(a)') '  OSMesa  not available: '//trim(why)
      else
         write (output_unit, '(a)') '  OSMesa  loaded, but no off-screen context could be created'
      end if
   end subroutine print_version

end program udec
