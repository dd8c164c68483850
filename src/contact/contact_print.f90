!> PRINT BLOCK, CORNERS, CONTACT, DOMAIN, LIST for the block geometry.
!> Fixed columns, one entity per line, ids as accepted by other commands.
!> The optional range (xl xu yl yu) keeps entities whose reference point
!> (block centroid, corner, contact point, domain contact mean) is inside.
module contact_print
   use core_kinds, only: wp, ip
   use core_output, only: output_t
   use model_polygon, only: pi
   use model_geometry, only: geometry_t
   implicit none
   private
   public :: print_blocks, print_corners, print_contacts, print_domains, print_list

contains

   logical function in_range(x, y, range)
      real(wp), intent(in) :: x, y
      real(wp), intent(in), optional :: range(4)
      in_range = .true.
      if (present(range)) in_range = x >= range(1) .and. x <= range(2) .and. &
                                     y >= range(3) .and. y <= range(4)
   end function in_range

   !> PRINT BLOCK: id, material, constitutive number, corners, area, centroid.
   subroutine print_blocks(geo, out, range)
      type(geometry_t), intent(in) :: geo
      type(output_t), intent(in) :: out
      real(wp), intent(in), optional :: range(4)
      character(len=100) :: text
      integer(ip) :: b
      call out%line('   BLOCK   MAT  CONS  CORN  FIRST          AREA      X-CENTRE      Y-CENTRE')
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         if (.not. in_range(geo%blocks%xc(b), geo%blocks%yc(b), range)) cycle
         write (text, '(i8,3i6,i7,3es14.5)') b, geo%blocks%material(b), geo%blocks%cons(b), &
            geo%blocks%ncorner(b), geo%blocks%first_corner(b), geo%blocks%area(b), &
            geo%blocks%xc(b), geo%blocks%yc(b)
         call out%line(text)
      end do
   end subroutine print_blocks

   !> PRINT CORNERS: id, block, coordinates, ring links, rounding radius.
   subroutine print_corners(geo, out, range)
      type(geometry_t), intent(in) :: geo
      type(output_t), intent(in) :: out
      real(wp), intent(in), optional :: range(4)
      character(len=100) :: text
      integer(ip) :: c
      call out%line('  CORNER   BLOCK             X             Y    NEXT    PREV        RADIUS')
      do c = 1, geo%corners%n
         if (.not. geo%corners%live(c)) cycle
         if (.not. in_range(geo%corners%x(c), geo%corners%y(c), range)) cycle
         write (text, '(2i8,2es14.5,2i8,es14.5)') c, geo%corners%block(c), geo%corners%x(c), &
            geo%corners%y(c), geo%corners%next(c), geo%corners%prev(c), geo%corners%radius(c)
         call out%line(text)
      end do
   end subroutine print_corners

   !> PRINT CONTACT (STATE): materials, cons, length, normal angle, type, blocks.
   subroutine print_contacts(geo, out, range)
      type(geometry_t), intent(in) :: geo
      type(output_t), intent(in) :: out
      real(wp), intent(in), optional :: range(4)
      character(len=130) :: text
      integer(ip) :: c
      real(wp) :: angle
      call out%line(' CONTACT  BLOCK1  BLOCK2 TYPE  JMAT JCONS        LENGTH  ANGLE' // &
                    '             X             Y    DOM1    DOM2')
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         if (.not. in_range(geo%contacts%x(c), geo%contacts%y(c), range)) cycle
         angle = atan2(geo%contacts%ny(c), geo%contacts%nx(c))*180.0_wp/pi
         write (text, '(3i8,i5,2i6,es14.5,f7.1,2es14.5,2i8)') c, geo%contacts%block1(c), &
            geo%contacts%block2(c), geo%contacts%kind(c), geo%contacts%jmat(c), &
            geo%contacts%jcons(c), geo%contacts%length(c), angle, geo%contacts%x(c), &
            geo%contacts%y(c), geo%contacts%dom1(c), geo%contacts%dom2(c)
         call out%line(text)
      end do
   end subroutine print_contacts

   !> PRINT DOMAIN: id, area, number of contacts, outer flag, then the
   !> contacts around it (ten per line).
   subroutine print_domains(geo, out, range)
      type(geometry_t), intent(in) :: geo
      type(output_t), intent(in) :: out
      real(wp), intent(in), optional :: range(4)
      character(len=100) :: text
      integer(ip) :: d, k, f, n, j
      real(wp) :: xm, ym
      call out%line('  DOMAIN          AREA  NCON OUTER  CONTACTS')
      do d = 1, geo%domains%n
         if (.not. geo%domains%live(d)) cycle
         f = geo%domains%first(d)
         n = geo%domains%count(d)
         if (present(range)) then
            xm = 0.0_wp
            ym = 0.0_wp
            do k = f, f + n - 1
               xm = xm + geo%contacts%x(geo%domains%ring(k))/real(n, wp)
               ym = ym + geo%contacts%y(geo%domains%ring(k))/real(n, wp)
            end do
            if (.not. in_range(xm, ym, range)) cycle
         end if
         write (text, '(i8,es14.5,i6,l6)') d, geo%domains%area(d), n, geo%domains%outer(d)
         do k = 0, n - 1, 10
            j = min(n - 1, k + 9)
            if (k == 0) then
               write (text(37:), '(10i6)') geo%domains%ring(f + k:f + j)
            else
               text = ''
               write (text(37:), '(10i6)') geo%domains%ring(f + k:f + j)
            end if
            call out%line(text)
         end do
         if (n == 0) call out%line(text)
      end do
   end subroutine print_domains

   !> PRINT LIST: the block linked list, each block with its clockwise corners.
   subroutine print_list(geo, out)
      type(geometry_t), intent(in) :: geo
      type(output_t), intent(in) :: out
      character(len=100) :: text
      integer(ip) :: b, c, k, col
      call out%line('   BLOCK  CORNERS (clockwise)')
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         text = ''
         write (text(1:8), '(i8)') b
         col = 9
         c = geo%blocks%first_corner(b)
         do k = 1, geo%blocks%ncorner(b)
            if (col > 81) then
               call out%line(text)
               text = ''
               col = 9
            end if
            write (text(col:col + 7), '(i8)') c
            col = col + 8
            c = geo%corners%next(c)
         end do
         call out%line(text)
      end do
   end subroutine print_list

end module contact_print
