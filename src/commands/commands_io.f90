!> SAVE, RESTART and SET XFORM (manual Section 4.5). The save file is HDF5
!> (io_schema); it is portable between machines whatever XFORM says.
module commands_io
   use core_error, only: error_t, set_error
   use core_output, only: output_t
   use model_state, only: model_t
   use commands_parser, only: parsed_t
   use commands_context, only: context_t, registry_t, context_read_name
   use engine_stages, only: cycle_report_t
   use io_schema, only: io_save_model, io_load_model
   use commands_address, only: run_dump, run_set_word
   use core_files, only: leftover_temporaries
   use commands_grammar, only: match_none
   implicit none
   private
   public :: register_io_commands
   public :: handle_save, set_xform, default_save_file

   !> The manual speaks of "the default file" for SAVE and RESTART without a
   !> name but does not name it; we use UDEC.SAV, after UDEC.INI and UDEC.LOG.
   character(len=*), parameter :: default_save_file = 'UDEC.SAV'

contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_io_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('io', 'SAve', '[s]', '', '', '4.5', 'save the model to a file (HDF5)', &
                   handler=handle_save, default='UDEC.SAV')
      call reg%add('io', 'Restart', '[s]', '', '', '4.5', 'restore a saved model', run_restart, &
                   default='UDEC.SAV')
      call reg%add('io', 'DUmp', 'ii', '', '', '4.5', &
                   'list the 1989 records between two addresses by field (DU: D is DAMPING)', &
                   run_dump, args='n m')
      call reg%add('io', 'ISET', 'iii', '', '', '4.5', &
                   'set an integer word: value, 1989 address, offset (Section 6.1)', &
                   run_set_word, args='ival ia ioff')
      call reg%add('io', 'RSet', 'rii', '', '', '4.5', &
                   'set a real word: value, 1989 address, offset (Section 6.1)', run_set_word, &
                   args='v ia ioff')
      call reg%add_set('io', 'Xform', set_io)
   end subroutine register_io_commands

   !> SAVE [file]
   subroutine handle_save(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: file, first
      integer :: count
      associate (model => ctx%model, out => ctx%out)
         file = file_argument(parsed)
         ! a SAVE killed midway (SIGKILL, power cut) leaves its temporary: it
         ! never replaced the file, is not read, and is named here once more
         call leftover_temporaries(file, count, first)
         if (count > 0) call out%line("SAVE: note: '"//first//"'"// &
                                      trim(merge(' and others   ', ' (a temporary)', count > 1))// &
                                      " was left by a SAVE to '"//file//"' that did not " // &
                                      "finish; "// &
                                      'it is not the save file and may be deleted')
         call io_save_model(model, file, error)
         if (allocated(error)) then
            error%message = 'SAVE: '//error%message
            return
         end if
         call out%line("Model saved to '"//file//"'.")
      end associate
   end subroutine handle_save

   !> SET XFORM ON|OFF: accepted for old decks. The manual's choice between a
   !> portable formatted file and a smaller binary one does not arise: the
   !> HDF5 save file is binary and portable, so the setting has no effect.
   subroutine set_xform(parsed, k, error)
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      type(error_t), allocatable, intent(out) :: error
      if (k < parsed%nitems) then
         select case (parsed%items(k + 1)%name)
         case ('ON', 'OFF')
            return
         end select
      end if
      call set_error(error, 'SET XFORM: expected ON or OFF after XFORM')
   end subroutine set_xform

   function file_argument(parsed) result(file)
      type(parsed_t), intent(in) :: parsed
      character(len=:), allocatable :: file
      file = default_save_file
      if (parsed%nitems < 1) return
      if (parsed%items(1)%name == '' .and. parsed%items(1)%count > 0) &
         file = parsed%text_at(1, 1)
   end function file_argument

   !> RESTART [file]: the model is replaced only when the whole file was read.
   subroutine run_restart(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      character(len=:), allocatable :: file
      file = context_read_name(ctx, 'RESTART', file_argument(parsed))
      call io_load_model(ctx%model, file, error)
      if (allocated(error)) then
         error%message = 'RESTART: '//error%message//'; the model in memory is unchanged'
         if (reset_word(file_argument(parsed))) error%message = error%message// &
            '. Did you mean RESET? RESET is spelled in full, as in the manual''s decks '// &
            '(R, RE, RES .. RESTAR abbreviate RESTART)'
         return
      end if
      call ctx%out%line("Model restored from '"//file//"'.")
      if (len(ctx%model%heading) > 0) call ctx%out%line('  '//ctx%model%heading)
      ! PRINT CYCLE times the restored model's CYCLEs only
      ctx%cycle = cycle_report_t()
   contains
      !> A file name that is one of RESET's keywords (DISP, HIST, TIME ..) as
      !> the command grammar reads them: a user typed RES DISP meaning RESET.
      logical function reset_word(word)
         character(len=*), intent(in) :: word
         integer :: k
         reset_word = .false.
         if (len_trim(word) == 0) return
         k = ctx%grammar%find_command('RESET')
         if (k <= 0) return
         reset_word = ctx%grammar%commands(k)%find_keyword(word) /= match_none
      end function reset_word
   end subroutine run_restart

   !> SET XFORM ON | OFF.
   subroutine set_io(ctx, parsed, k, apply, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      integer, intent(in) :: k
      logical, intent(in) :: apply
      type(error_t), allocatable, intent(out) :: error
      if (.not. apply .or. ctx%check_only) return   ! XFORM only checks its ON / OFF
      call set_xform(parsed, k, error)
   end subroutine set_io

end module commands_io
