!> File helpers: output files are written to a temporary beside the target and
!> renamed into place, so a reader never sees a half-written file.
module core_files
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
   use core_error, only: error_t, set_error
   implicit none
   private
   public :: file_rename, file_delete, temporary_name
   public :: file_kind, file_kind_name, check_output_file, check_input_file, folder_of
   public :: leftover_temporaries, temporary_marker, case_match, c_string_text
   public :: kind_missing, kind_regular, kind_folder, kind_unknown

   !> file_kind results (core_stat.c)
   integer, parameter :: kind_unknown = -1, kind_missing = 0, kind_regular = 1, kind_folder = 2
   !> What each kind (kind_unknown .. 6: 3 and 4 character and block
   !> devices, 5 FIFO, 6 socket) is called in messages.
   character(len=*), parameter :: kind_names(-1:6) = [character(len=19) :: &
      'not accessible', 'missing', 'a regular file', 'a folder', 'a device', 'a device', &
      'a FIFO (named pipe)', 'a socket']
   !> Part of every temporary's name: `<target>.udec-tmp[pid]`.
   character(len=*), parameter :: temporary_marker = '.udec-tmp'
   !> c_count_entries: names starting with the key, or equal to it but for case
   integer(c_int), parameter :: entries_prefixed = 0, entries_case = 1

   interface
      !> C library rename(3): replaces `new` atomically on POSIX systems.
      function c_rename(old, new) bind(c, name='rename') result(status)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: old(*), new(*)
         integer(c_int) :: status
      end function c_rename
      function c_file_kind(path) bind(c, name='udec_file_kind') result(kind)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: kind
      end function c_file_kind
      !> Entries of folder `dir` named like `key`: `how` entries_prefixed or
      !> entries_case (core_stat.c); the first one's name into `first`.
      function c_count_entries(dir, key, how, first, nfirst) bind(c, name='udec_count_entries') &
         result(count)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: dir(*), key(*)
         integer(c_int), value :: how, nfirst
         character(kind=c_char), intent(out) :: first(*)
         integer(c_int) :: count
      end function c_count_entries
   end interface

contains

   !> Name of the temporary written before `name` is renamed into place.
   pure function temporary_name(name) result(temp)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: temp
      temp = name//temporary_marker
   end function temporary_name

   !> Rename file `from` to `to` (replacing `to`); `ok` false on failure.
   subroutine file_rename(from, to, ok)
      character(len=*), intent(in) :: from, to
      logical, intent(out) :: ok
      ok = c_rename(from//c_null_char, to//c_null_char) == 0_c_int
   end subroutine file_rename

   !> Delete file `name` if it exists.
   subroutine file_delete(name)
      character(len=*), intent(in) :: name
      integer :: u, ios
      logical :: exists
      inquire (file=name, exist=exists)
      if (.not. exists) return
      open (newunit=u, file=name, status='old', iostat=ios)
      if (ios == 0) close (u, status='delete', iostat=ios)
   end subroutine file_delete

   !> What `path` names: kind_missing, kind_regular, kind_folder, 3 character
   !> device, 4 block device, 5 FIFO, 6 socket, 7 other, kind_unknown when it
   !> cannot be examined.
   integer function file_kind(path) result(kind)
      character(len=*), intent(in) :: path
      kind = int(c_file_kind(path//c_null_char))
   end function file_kind

   !> 'a folder', 'a device', ... for messages.
   function file_kind_name(kind) result(text)
      integer, intent(in) :: kind
      character(len=:), allocatable :: text
      if (kind >= lbound(kind_names, 1) .and. kind <= ubound(kind_names, 1)) then
         text = trim(kind_names(kind))
      else
         text = 'not a regular file'
      end if
   end function file_kind_name

   !> `command: ` to begin a message ('' without a command).
   pure function lead(command) result(text)
      character(len=*), intent(in) :: command
      character(len=:), allocatable :: text
      text = ''
      if (len(command) > 0) text = command//': '
   end function lead

   !> The folder part of `path` ('.' when it has none).
   function folder_of(path) result(folder)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: folder
      integer :: k
      k = index(path, '/', back=.true.)
      if (k == 0) then
         folder = '.'
      else if (k == 1) then
         folder = '/'
      else
         folder = path(1:k - 1)
      end if
   end function folder_of

   !> An output file (SAVE, COPY, HIST WRITE, PRINT FILE, OUT) must be a
   !> regular file or a new name in an existing folder: a folder, device,
   !> FIFO or missing folder is refused before anything is written (a rename
   !> onto it would replace it). `command` begins the message.
   subroutine check_output_file(command, path, error)
      character(len=*), intent(in) :: command, path
      type(error_t), allocatable, intent(out) :: error
      integer :: kind, parent
      if (len_trim(path) == 0) then
         call set_error(error, lead(command)//'the file name is empty')
         return
      end if
      kind = file_kind(path)
      select case (kind)
      case (kind_regular)
         return
      case (kind_missing)
         parent = file_kind(folder_of(path))
         if (parent /= kind_folder) then
            call set_error(error, lead(command)//"cannot open '"//path// &
                           "' for writing: the folder '"//folder_of(path)//"' does not exist")
         end if
      case default
         call set_error(error, lead(command)//"cannot open '"//path//"' for writing: it is "// &
                        file_kind_name(kind)//', not a regular file; give a file name')
      end select
   end subroutine check_output_file

   !> A command file (CALL, the batch file) must exist and not be a folder or
   !> a device.
   subroutine check_input_file(command, path, error)
      character(len=*), intent(in) :: command, path
      type(error_t), allocatable, intent(out) :: error
      integer :: kind
      kind = file_kind(path)
      select case (kind)
      case (kind_regular, 5)
         return
      case (kind_missing)
         call set_error(error, lead(command)//"cannot open file '"//path//"': no such file")
      case default
         call set_error(error, lead(command)//"cannot read '"//path//"': it is "// &
                        file_kind_name(kind)//', not a text file of commands')
      end select
   end subroutine check_input_file

   !> The file a reading command (CALL, RESTART) takes for `path`: `path`
   !> itself when it exists; else, as the manual's decks were written under
   !> DOS (CALL TUNNEL.DAT, RESTART X.SAV in any case), the one file of its
   !> folder whose name differs only in letter case. `count` is the number
   !> of such files (0 when `path` exists or none does; `found` is `path`
   !> unless count is 1). Writing commands keep the user's spelling.
   subroutine case_match(path, found, count)
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: found
      integer, intent(out) :: count
      character(len=:), allocatable :: first
      integer :: k
      found = path
      count = 0
      if (file_kind(path) /= kind_missing) return
      k = index(path, '/', back=.true.)
      if (k == len(path)) return
      call folder_entries(path, path(k + 1:), entries_case, count, first)
      if (count /= 1) return
      found = path(1:k)//first
   end subroutine case_match

   !> The text of a NUL-terminated C string in `buffer`.
   pure function c_string_text(buffer) result(text)
      character(kind=c_char, len=1), intent(in) :: buffer(:)
      character(len=:), allocatable :: text
      integer :: k, n
      n = 0
      do while (n < size(buffer))
         if (buffer(n + 1) == c_null_char) exit
         n = n + 1
      end do
      allocate (character(len=n) :: text)
      do k = 1, n
         text(k:k) = buffer(k)
      end do
   end function c_string_text

   !> Temporaries `<path>.udec-tmp*` beside `path` (left by a SAVE that was
   !> killed): their number and the first one's name.
   subroutine leftover_temporaries(path, count, first)
      character(len=*), intent(in) :: path
      integer, intent(out) :: count
      character(len=:), allocatable, intent(out) :: first
      integer :: k
      k = index(path, '/', back=.true.)
      call folder_entries(path, path(k + 1:)//temporary_marker, entries_prefixed, count, first)
      if (k > 0) first = folder_of(path)//'/'//first
   end subroutine leftover_temporaries

   !> The entries of the folder of `path` named like `key` (`how`, as
   !> c_count_entries): their number and the first one's name.
   subroutine folder_entries(path, key, how, count, first)
      character(len=*), intent(in) :: path, key
      integer(c_int), intent(in) :: how
      integer, intent(out) :: count
      character(len=:), allocatable, intent(out) :: first
      character(kind=c_char, len=1) :: buffer(1024)
      count = int(c_count_entries(folder_of(path)//c_null_char, key//c_null_char, how, buffer, &
                                  int(size(buffer), c_int)))
      first = c_string_text(buffer)
   end subroutine folder_entries

end module core_files
