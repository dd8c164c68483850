!> Input sources of the interpreter: files (DATA, UDEC.INI, CALLed files) and the
!> interactive prompt. A logical line joins physical lines ending in `&` and, in
!> files, following lines that begin with `+` (legacy continuation).
module commands_source
   use, intrinsic :: iso_fortran_env, only: iostat_end, iostat_eor, input_unit, output_unit
   use core_output, only: output_t
   use commands_tokens, only: strip_comment
   use core_lineedit, only: lineedit_active, lineedit_read
   implicit none
   private
   public :: source_t, source_open_file, source_open_stdin, source_close
   public :: source_read_logical, source_read_raw, max_line_length

   !> Longest logical line accepted (longer input is cut and reported).
   integer, parameter :: max_line_length = 1000000
   !> Longest physical line of a command file: a longer one (or a NUL byte)
   !> means the file is not text (CALL /dev/zero, a save file), issue 20.
   integer, parameter :: max_file_line = 10000

   type :: source_t
      integer :: unit = -1
      logical :: is_open = .false.               !< a file we opened (and must close)
      character(len=:), allocatable :: name      !< file name, or '<stdin>'
      logical :: interactive = .false.           !< reading the UDEC> prompt
      logical :: echo = .true.                   !< echo lines to the output
      !> UDEC.INI (manual 4.3, site defaults): an input error there is reported
      !> and the line skipped; the run goes on to the deck
      logical :: defaults = .false.
      integer :: line = 0                        !< physical lines read so far
      logical :: has_pending = .false.
      character(len=:), allocatable :: pending   !< one line of look-ahead
      !> why the file was not read to its end (not a text file); the
      !> interpreter reports it at line `line + 1`
      character(len=:), allocatable :: fault
   end type source_t

contains

   subroutine source_open_file(source, name, ok)
      type(source_t), intent(out) :: source
      character(len=*), intent(in) :: name
      logical, intent(out) :: ok
      integer :: ios
      open (newunit=source%unit, file=name, status='old', action='read', &
            form='formatted', access='sequential', iostat=ios)
      ok = ios == 0
      source%is_open = ok
      source%name = name
      source%interactive = .false.
   end subroutine source_open_file

   subroutine source_open_stdin(source)
      type(source_t), intent(out) :: source
      source%unit = input_unit
      source%name = '<stdin>'
      source%interactive = .true.
      source%echo = .false.
   end subroutine source_open_stdin

   subroutine source_close(source)
      type(source_t), intent(inout) :: source
      if (source%is_open) close (source%unit)
      source%is_open = .false.
      source%unit = -1
   end subroutine source_close

   !> Read one physical line of any length. `eof` is set at end of input.
   !> With `fault` (file sources), a NUL byte or a line longer than
   !> max_file_line ends the reading at once: `fault` says why and `eof` is set.
   subroutine read_physical(unit, text, eof, fault)
      integer, intent(in) :: unit
      character(len=:), allocatable, intent(out) :: text
      logical, intent(out) :: eof
      character(len=:), allocatable, intent(inout), optional :: fault
      character(len=4096) :: chunk
      integer :: ios, n
      text = ''
      eof = .false.
      do
         read (unit, '(a)', advance='no', iostat=ios, size=n) chunk
         if (present(fault)) then
            if (index(chunk(1:n), achar(0)) > 0) then
               fault = 'the file holds a NUL byte: it is not a text file of commands; '// &
                       'nothing more is read from it'
            else if (len(text) + n > max_file_line) then
               fault = 'a line longer than 10000 characters: this is not a text file of '// &
                       'commands; nothing more is read from it'
            end if
            if (allocated(fault)) then
               eof = .true.
               return
            end if
         end if
         if (len(text) < max_line_length) text = text//chunk(1:n)
         if (ios == iostat_eor) exit
         if (ios == iostat_end) then
            eof = len(text) == 0
            exit
         end if
         if (ios /= 0) then            ! unreadable record: treat as end of input
            eof = .true.
            exit
         end if
      end do
      if (len(text) > 0) then         ! tolerate CR-LF files
         if (text(len(text):len(text)) == char(13)) text = text(1:len(text) - 1)
      end if
   end subroutine read_physical

   !> Next physical line from the look-ahead buffer or the unit; echoed. As it
   !> is: no continuation, no comment stripping (HEADING reads its title so).
   subroutine source_read_raw(source, out, prompt, text, eof)
      type(source_t), intent(inout) :: source
      type(output_t), intent(in) :: out
      character(len=*), intent(in) :: prompt
      character(len=:), allocatable, intent(out) :: text
      logical, intent(out) :: eof
      eof = .true.
      if (allocated(source%fault)) return
      if (source%has_pending) then
         text = source%pending
         source%has_pending = .false.
         source%line = source%line + 1
         eof = .false.
      else
         if (source%interactive .and. lineedit_active()) then
            ! a terminal: libedit's line editing, history and completion
            call lineedit_read(prompt, text, eof)
         else if (source%interactive) then
            write (output_unit, '(a)', advance='no') prompt
            flush (output_unit)
            call read_physical(source%unit, text, eof)
         else
            call read_physical(source%unit, text, eof, source%fault)
         end if
         if (eof) return
         source%line = source%line + 1
      end if
      if (source%echo) call out%line(text)
   end subroutine source_read_raw

   !> Read one logical line: the code (comments removed, continuations joined)
   !> and the physical line number where it started.
   subroutine source_read_logical(source, out, prompt, code, first_line, eof, too_long)
      type(source_t), intent(inout) :: source
      type(output_t), intent(in) :: out
      character(len=*), intent(in) :: prompt
      character(len=:), allocatable, intent(out) :: code
      integer, intent(out) :: first_line
      logical, intent(out) :: eof, too_long
      character(len=:), allocatable :: text, part
      logical :: more
      too_long = .false.
      call source_read_raw(source, out, prompt, text, eof)
      if (eof) return
      first_line = source%line
      code = ''
      part = strip_comment(text)
      do
         call take_continuation(part, more)
         call append(code, part, too_long)
         if (.not. more) exit
         call source_read_raw(source, out, '+ ', text, eof)
         if (eof) then
            eof = .false.          ! a dangling '&' at end of file ends the command
            exit
         end if
         part = strip_comment(text)
      end do
      if (source%interactive) return
      ! Legacy '+' continuation: look ahead one physical line.
      do
         call read_physical(source%unit, text, more, source%fault)
         if (allocated(source%fault)) exit    ! reported when the next line is asked
         if (more) exit                       ! end of file: nothing pending
         part = adjustl(strip_comment(text))
         if (len_trim(part) > 0) then
            if (part(1:1) == '+') then
               source%line = source%line + 1
               if (source%echo) call out%line(text)
               part = part(2:)
               call take_continuation(part, more)
               call append(code, part, too_long)
               cycle
            end if
         end if
         source%pending = text
         source%has_pending = .true.       ! counted and echoed when consumed
         exit
      end do
   end subroutine source_read_logical

   !> Remove a trailing `&` from `part`; `more` tells whether one was there.
   subroutine take_continuation(part, more)
      character(len=:), allocatable, intent(inout) :: part
      logical, intent(out) :: more
      integer :: n
      n = len_trim(part)
      more = .false.
      if (n > 0) then
         if (part(n:n) == '&') then
            more = .true.
            part = part(1:n - 1)
         end if
      end if
   end subroutine take_continuation

   subroutine append(code, part, too_long)
      character(len=:), allocatable, intent(inout) :: code
      character(len=*), intent(in) :: part
      logical, intent(inout) :: too_long
      if (len(code) + len(part) + 1 > max_line_length) then
         too_long = .true.
         return
      end if
      code = code//' '//part
   end subroutine append

end module commands_source
