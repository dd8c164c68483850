!> The last geometry commands of manual Sections 4.5 and 4.6: JPLOT START|STOP
!> (record CRACK and JSET joints for plotting without splitting blocks) and
!> LINK x1 y1 x2 y2 (validated; contacts are found by the global detection, so
!> no link is stored). See docs/geometry.md for the deviations.
module commands_geometry_extras
   use core_kinds, only: wp, ip
   use core_error, only: error_t, set_error
   use core_output, only: output_t
   use model_state, only: model_t
   use model_geometry, only: geometry_t, geometry_block_polygon
   use geometry_polygon, only: point_in_polygon, polygon_boundary_distance
   use commands_parser, only: parsed_t
   use commands_context, only: context_t, registry_t, require_block
   use commands_numbers, only: format_real
   implicit none
   private
   public :: register_geometry_extras_commands
   public :: handle_jplot, handle_link, find_block_at

contains

   !> The commands of this family in the registry (commands_context).
   subroutine register_geometry_extras_commands(reg)
      type(registry_t), intent(inout) :: reg
      call reg%add('geometry', 'JPLot', '', '', 'START;STOP', '4.6', &
                   'preview the joints of CRACK and JSET before cutting', handler=handle_jplot)
      call reg%add('geometry', 'LInk', 'rrrr', '', '', '4.5', &
                   'link a flying block to the block beside it (LI: L is LINK or LOAD)', &
                   handler=handle_link, args='x1 y1 x2 y2')
   end subroutine register_geometry_extras_commands

   !> JPLOT START clears the list and starts recording; JPLOT STOP ends it.
   subroutine handle_jplot(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      logical :: start, finish
      character(len=120) :: text
      associate (model => ctx%model, out => ctx%out)
         start = parsed%find('START') > 0
         finish = parsed%find('STOP') > 0
         if (start .eqv. finish) then
            call set_error(error, 'JPLOT: expected exactly one of START or STOP')
            return
         end if
         associate (j => model%geometry%jplot)
            if (start) then
               j%n = 0
               j%on = .true.
               call out%line('JPLOT START: CRACK and JSET joints are recorded for plotting; ' &
                             //'blocks are not split until JPLOT STOP')
            else if (.not. j%on) then
               call out%line('JPLOT STOP: recording was not on (no JPLOT START)')
            else
               j%on = .false.
               write (text, '(a,i0,a)') 'JPLOT STOP: ', j%n, &
                  ' joint segment(s) recorded; blocks were not split'
               call out%line(trim(text))
            end if
         end associate
      end associate
   end subroutine handle_jplot

   !> LINK x1 y1 x2 y2: (x1,y1) inside the "flying" block, (x2,y2) inside the
   !> block it is linked to. Both must be strictly inside two different live
   !> blocks. Nothing is stored: contact detection bins every block globally,
   !> so contacts between any blocks are found without a link.
   subroutine handle_link(ctx, parsed, error)
      type(context_t), intent(inout) :: ctx
      type(parsed_t), intent(in) :: parsed
      type(error_t), allocatable, intent(out) :: error
      real(wp) :: p(4)
      integer(ip) :: b(2)
      logical :: on_edge
      integer :: k
      character(len=160) :: text
      character(len=*), parameter :: which(2) = ['first ', 'second']
      associate (model => ctx%model, out => ctx%out)
         call require_block(model, 'LINK', error)
         if (allocated(error)) return
         do k = 1, 4
            p(k) = parsed%real_at(1, k)
         end do
         do k = 1, 2
            call find_block_at(model%geometry, p(2*k - 1), p(2*k), b(k), on_edge)
            if (b(k) == 0) then
               call set_error(error, 'LINK: the '//trim(which(k))//' point '// &
                              point_text(p(2*k - 1), p(2*k))//' is not inside any block')
               return
            end if
            if (on_edge) then
               write (text, '(i0)') b(k)
               call set_error(error, 'LINK: the '//trim(which(k))//' point '// &
                              point_text(p(2*k - 1), p(2*k))//' lies on the boundary of block ' &
                              //trim(text)//'; give a point inside the block')
               return
            end if
         end do
         if (b(1) == b(2)) then
            write (text, '(i0)') b(1)
            call set_error(error, 'LINK: both points lie inside block '//trim(text)// &
                           '; give points inside two different blocks')
            return
         end if
         write (text, '(a,i0,a,i0,a)') 'LINK: blocks ', b(1), ' and ', b(2), &
            ' need no link; contacts between them are found automatically'
         call out%line(trim(text))
      end associate
   end subroutine handle_link

   !> The live block containing (x, y), 0 if none. `on_edge` when the point is
   !> within the geometric tolerance of that block's boundary.
   subroutine find_block_at(geo, x, y, block, on_edge)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: x, y
      integer(ip), intent(out) :: block
      logical, intent(out) :: on_edge
      integer(ip) :: b
      real(wp), allocatable :: px(:), py(:)
      block = 0
      on_edge = .false.
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         if (x < geo%blocks%xmin(b) - geo%tol .or. x > geo%blocks%xmax(b) + geo%tol) cycle
         if (y < geo%blocks%ymin(b) - geo%tol .or. y > geo%blocks%ymax(b) + geo%tol) cycle
         call geometry_block_polygon(geo, b, px, py)
         if (polygon_boundary_distance(px, py, x, y) <= geo%tol) then
            block = b
            on_edge = .true.
            return
         end if
         if (point_in_polygon(px, py, x, y)) then
            block = b
            return
         end if
      end do
   end subroutine find_block_at

   function point_text(x, y) result(text)
      real(wp), intent(in) :: x, y
      character(len=:), allocatable :: text
      text = '('//format_real(x)//', '//format_real(y)//')'
   end function point_text

end module commands_geometry_extras
