!> PROPERTY, GRAVITY and PRINT PROPERTY (manual Section 4.5).
module commands_properties
   use core_kinds, only: wp
   use core_error, only: error_t, set_error
   use core_output, only: output_t, fmt_real
   use model_state, only: model_t
   use model_materials, only: canonical_property, property_names, &
                              nproperties
   use commands_parser, only: parsed_t
   implicit none
   private
   public :: handle_property, handle_gravity, print_properties

contains

   !> PROPERTY MAT n | JMAT n keyword v ... : validate every pair, then store.
   !> MAT and JMAT index one table; a later MAT/JMAT on the line switches the
   !> material the following values go to.
   subroutine handle_property(model, parsed, error)
      type(model_t), intent(inout) :: model
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      integer :: k, mat, first
      first = 0
      do k = 1, parsed%nitems
         if (parsed%items(k)%keyword > 0) then
            first = k
            exit
         end if
      end do
      if (first == 0) then
         call set_error(error, 'PROPERTY: expected MAT n or JMAT n followed by properties')
         return
      end if
      select case (parsed%items(first)%name)
      case ('MATERIAL', 'JMATERIAL')
      case default
         call set_error(error, 'PROPERTY: the first keyword must be MAT n or JMAT n, got ' &
                        //parsed%items(first)%name)
         return
      end select
      ! All values were range-checked by the parser (properties are >= 0, except
      ! the exponents JEN/JES and AZERO); nothing more can fail, so store.
      mat = 0
      do k = first, parsed%nitems
         select case (parsed%items(k)%name)
         case ('MATERIAL', 'JMATERIAL')
            mat = parsed%int_at(k, 1)
         case ('COND')
            call model%materials%set(mat, 'XCOND', parsed%real_at(k, 1))
            call model%materials%set(mat, 'YCOND', parsed%real_at(k, 1))
         case default
            call model%materials%set(mat, canonical_property(parsed%items(k)%name), &
                                     parsed%real_at(k, 1))
         end select
      end do
   end subroutine handle_property

   !> GRAVITY gx gy (also SET GRAVITY).
   subroutine handle_gravity(model, gx, gy)
      type(model_t), intent(inout) :: model
      real(wp), intent(in) :: gx, gy
      model%gravity = [gx, gy]
   end subroutine handle_gravity

   !> PRINT PROPERTY: every material with its given properties, fixed columns.
   !> With `only`, just the properties named there (PRINT PROPERTY <kind>).
   subroutine print_properties(model, out, only)
      type(model_t), intent(in) :: model
      type(output_t), intent(in) :: out
      character(len=*), intent(in), optional :: only(:)
      integer :: mat, k
      logical :: any_printed
      character(len=80) :: line
      call out%line('')
      call out%line('  material  property        value')
      call out%line('  --------  ----------  --------------')
      any_printed = .false.
      do mat = 1, model%materials%nmat
         do k = 1, nproperties
            if (.not. model%materials%given(k, mat)) cycle
            if (present(only)) then
               if (all(only /= property_names(k))) cycle
            end if
            write (line, '(2x,i8,2x,a10,2x,a)') mat, property_names(k), &
               fmt_real(model%materials%value(k, mat), 14, 6)
            call out%line(line)
            any_printed = .true.
         end do
      end do
      if (.not. any_printed) call out%line('  (no properties given)')
   end subroutine print_properties

end module commands_properties
