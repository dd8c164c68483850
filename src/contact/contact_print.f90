!> PRINT tables of the block lists: BLOCK, RIGID, CORNERS, CONTACT (STATE,
!> DISP, FORCE), DOMAIN, LIST, DLIST. Fixed columns (docs/print.md), one
!> entity per line, ids as accepted by other commands. The optional range (any
!> of the three forms of core_range) keeps entities whose reference point is
!> inside: block centroid, corner, contact point, mean of a domain's contact
!> points. `material` > 0 keeps blocks of that material (PRINT MAT n).
module contact_print
   use core_kinds, only: wp, ip, i1
   use core_output, only: output_t, fmt_real
   use core_range, only: range_t, in_range
   use core_constants, only: pi
   use model_geometry, only: geometry_t
   use contact_joint_law, only: state_slip, state_tension, state_fractured
   implicit none
   private
   public :: print_block_table, print_corners, print_contact_table, print_sdef
   public :: print_domains, print_list, contact_table_names
   public :: print_domain_list, contact_flags_text, domain_centre

   !> The tables of PRINT CONTACT, in the order PRINT CONTACT alone prints them.
   character(len=13), parameter :: contact_table_names(3) = &
      [character(len=13) :: 'STATE', 'DISPLACEMENTS', 'FORCES']

contains

   logical function block_selected(geo, b, range, material)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: b
      type(range_t), intent(in), optional :: range
      integer(ip), intent(in), optional :: material
      block_selected = geo%blocks%live(b)
      if (.not. block_selected) return
      block_selected = in_range(geo%blocks%xc(b), geo%blocks%yc(b), range)
      if (.not. block_selected .or. .not. present(material)) return
      if (material > 0) block_selected = geo%blocks%material(b) == material
   end function block_selected

   !> A live contact whose point is inside `range` (PRINT CONTACT tables).
   logical function contact_selected(geo, c, range)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      type(range_t), intent(in), optional :: range
      contact_selected = geo%contacts%live(c)
      if (contact_selected) contact_selected = in_range(geo%contacts%x(c), geo%contacts%y(c), range)
   end function contact_selected

   !> One block table, `which` = BLOCKS or RIGID; a block is in the range
   !> when its centroid is.
   !>   BLOCKS: id, material, constitutive number, corners, area, centroid.
   !>   RIGID: mass, centroid velocity, angular velocity, accumulated
   !>   displacement and rotation, FIX flag of each block.
   subroutine print_block_table(geo, out, which, range, material)
      type(geometry_t), intent(in) :: geo
      type(output_t), intent(in) :: out
      character(len=*), intent(in) :: which
      type(range_t), intent(in), optional :: range
      integer(ip), intent(in), optional :: material
      character(len=120) :: text
      integer(ip) :: b
      if (which == 'RIGID') then
         call out%line('   BLOCK          MASS         X-VEL         Y-VEL       ANG-VEL' // &
                       '        X-DISP        Y-DISP      ROTATION FIX')
      else
         call out%line('   BLOCK   MAT  CONS  CORN  FIRST          AREA      X-CENTRE      Y-CENTRE  ADDRESS')
      end if
      associate (bl => geo%blocks)
         do b = 1, bl%n
            if (.not. block_selected(geo, b, range, material)) cycle
            if (which == 'RIGID') then
               write (text, '(i8,7a,l4)') b, fmt_real(bl%mass(b)), fmt_real(bl%vx(b)), &
                  fmt_real(bl%vy(b)), fmt_real(bl%vr(b)), fmt_real(bl%ux(b)), fmt_real(bl%uy(b)), &
                  fmt_real(bl%rot(b)), bl%fixed(b)
            else
               write (text, '(i8,3i6,i7,3a,i9)') b, bl%material(b), bl%cons(b), bl%ncorner(b), &
                  bl%first_corner(b), fmt_real(bl%area(b)), fmt_real(bl%xc(b)), fmt_real(bl%yc(b)), &
                  bl%addr(b)
            end if
            call out%line(text)
         end do
      end associate
   end subroutine print_block_table

   !> PRINT SDEF (and with PRINT BLOCK): the simply-deformable blocks, their
   !> strains (exy tensor shear), stresses (tension positive), principal
   !> stresses and state (CONS 4: F once fractured). `any_sdef` false: the
   !> model has none, one line says so.
   subroutine print_sdef(geo, out, range, material, quiet)
      type(geometry_t), intent(in) :: geo
      type(output_t), intent(in) :: out
      type(range_t), intent(in), optional :: range
      integer(ip), intent(in), optional :: material
      logical, intent(in), optional :: quiet
      character(len=200) :: text
      integer(ip) :: b
      real(wp) :: c, r
      logical :: any_sdef
      any_sdef = .false.
      do b = 1, geo%blocks%n
         if (geo%blocks%live(b) .and. geo%blocks%sdef(b) .and. .not. geo%blocks%fdef(b)) &
            any_sdef = .true.
      end do
      if (.not. any_sdef) then
         if (present(quiet)) then
            if (quiet) return
         end if
         call out%line('No SDEF blocks (CHANGE SDEF makes blocks simply deformable)')
         return
      end if
      call out%line('SDEF blocks: strains (EXY tensor shear) and stresses (tension positive)')
      call out%line('   BLOCK CONS           EXX           EYY           EXY           SXX' // &
                    '           SYY           SXY          SIG1          SIG2 STATE')
      do b = 1, geo%blocks%n
         if (.not. (geo%blocks%sdef(b) .and. .not. geo%blocks%fdef(b))) cycle
         if (.not. block_selected(geo, b, range, material)) cycle
         c = 0.5_wp*(geo%blocks%sxx(b) + geo%blocks%syy(b))
         r = hypot(0.5_wp*(geo%blocks%sxx(b) - geo%blocks%syy(b)), geo%blocks%sxy(b))
         write (text, '(i8,i5,8a,a)') b, geo%blocks%cons(b), fmt_real(geo%blocks%exx(b)), &
            fmt_real(geo%blocks%eyy(b)), fmt_real(geo%blocks%exy(b)), fmt_real(geo%blocks%sxx(b)), &
            fmt_real(geo%blocks%syy(b)), fmt_real(geo%blocks%sxy(b)), fmt_real(c + r), &
            fmt_real(c - r), merge('    F', '    E', geo%blocks%bstate(b) == 4)
         call out%line(text)
      end do
   end subroutine print_sdef

   !> PRINT CORNERS: id, block, coordinates, ring links, rounding radius.
   subroutine print_corners(geo, out, range)
      type(geometry_t), intent(in) :: geo
      type(output_t), intent(in) :: out
      type(range_t), intent(in), optional :: range
      character(len=100) :: text
      integer(ip) :: c
      call out%line('  CORNER   BLOCK             X             Y    NEXT    PREV        RADIUS  ADDRESS')
      do c = 1, geo%corners%n
         if (.not. geo%corners%live(c)) cycle
         if (.not. in_range(geo%corners%x(c), geo%corners%y(c), range)) cycle
         write (text, '(2i8,2a,2i8,a,i9)') c, geo%corners%block(c), fmt_real(geo%corners%x(c)), &
            fmt_real(geo%corners%y(c)), geo%corners%next(c), geo%corners%prev(c), &
            fmt_real(geo%corners%radius(c)), geo%corners%addr(c)
         call out%line(text)
      end do
   end subroutine print_corners

   !> The state bits of a contact as three letters: S slip, T tension
   !> (opened), F fractured; '-' for a bit that is clear.
   pure function contact_flags_text(flags) result(text)
      integer(i1), intent(in) :: flags
      character(len=3) :: text
      text = '---'
      if (iand(flags, state_slip) /= 0) text(1:1) = 'S'
      if (iand(flags, state_tension) /= 0) text(2:2) = 'T'
      if (iand(flags, state_fractured) /= 0) text(3:3) = 'F'
   end function contact_flags_text

   !> One PRINT CONTACT table, `which` = STATE, DISPLACEMENTS or FORCES; a
   !> contact is in the range when its contact point is.
   !>   STATE: blocks, type, joint material and law, length, normal angle,
   !>   position, domains, state flags.
   !>   DISPLACEMENTS: accumulated shear (us) and normal (un, opening
   !>   positive) displacement and the gap of the rounded surfaces.
   !>   FORCES: normal (compression positive) and shear force; for a contact
   !>   of length > 0 also the stresses force/length (the manual prints
   !>   stress for joints with a length and force for point contacts).
   subroutine print_contact_table(geo, out, which, range)
      type(geometry_t), intent(in) :: geo
      type(output_t), intent(in) :: out
      character(len=*), intent(in) :: which
      type(range_t), intent(in), optional :: range
      character(len=140) :: text
      integer(ip) :: c
      real(wp) :: angle, length
      select case (which)
      case ('STATE')
         call out%line(' CONTACT  BLOCK1  BLOCK2 TYPE  JMAT JCONS        LENGTH  ANGLE' // &
                       '             X             Y    DOM1    DOM2 STATE  ADDRESS')
      case ('DISPLACEMENTS')
         call out%line(' CONTACT  BLOCK1  BLOCK2             X             Y' // &
                       '    SHEAR-DISP   NORMAL-DISP           GAP')
      case default
         call out%line(' CONTACT  BLOCK1  BLOCK2        LENGTH  NORMAL-FORCE   SHEAR-FORCE' // &
                       ' NORMAL-STRESS  SHEAR-STRESS')
      end select
      associate (co => geo%contacts, st => geo%contacts%state)
         do c = 1, co%n
            if (.not. contact_selected(geo, c, range)) cycle
            select case (which)
            case ('STATE')
               angle = atan2(co%ny(c), co%nx(c))*180.0_wp/pi
               write (text, '(3i8,i5,2i6,a,f7.1,2a,2i8,3x,a3,i9)') c, co%block1(c), co%block2(c), &
                  co%kind(c), co%jmat(c), co%jcons(c), fmt_real(co%length(c)), angle, &
                  fmt_real(co%x(c)), fmt_real(co%y(c)), co%dom1(c), co%dom2(c), &
                  contact_flags_text(st%flags(c)), co%addr(c)
            case ('DISPLACEMENTS')
               write (text, '(3i8,5a)') c, co%block1(c), co%block2(c), fmt_real(co%x(c)), &
                  fmt_real(co%y(c)), fmt_real(st%us(c)), fmt_real(st%un(c)), fmt_real(co%gap(c))
            case default
               length = co%length(c)
               write (text, '(3i8,3a)') c, co%block1(c), co%block2(c), fmt_real(length), &
                  fmt_real(st%fn(c)), fmt_real(st%fs(c))
               if (length > 0.0_wp) write (text(67:), '(2a)') fmt_real(st%fn(c)/length), &
                  fmt_real(st%fs(c)/length)
            end select
            call out%line(text)
         end do
      end associate
   end subroutine print_contact_table

   !> Mean of the contact points around domain `d` (its range reference point).
   subroutine domain_centre(geo, d, xm, ym)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: d
      real(wp), intent(out) :: xm, ym
      integer(ip) :: k, f, n
      f = geo%domains%first(d)
      n = geo%domains%count(d)
      xm = 0.0_wp
      ym = 0.0_wp
      do k = f, f + n - 1
         xm = xm + geo%contacts%x(geo%domains%ring(k))/real(n, wp)
         ym = ym + geo%contacts%y(geo%domains%ring(k))/real(n, wp)
      end do
   end subroutine domain_centre

   !> PRINT DOMAIN: id, area, number of contacts, outer flag, then the
   !> contacts around it (ten per line).
   subroutine print_domains(geo, out, range)
      type(geometry_t), intent(in) :: geo
      type(output_t), intent(in) :: out
      type(range_t), intent(in), optional :: range
      character(len=110) :: text
      integer(ip) :: d, f, n
      real(wp) :: xm, ym
      call out%line('  DOMAIN          AREA  NCON OUTER  ADDRESS  CONTACTS')
      do d = 1, geo%domains%n
         if (.not. geo%domains%live(d)) cycle
         f = geo%domains%first(d)
         n = geo%domains%count(d)
         if (present(range)) then
            call domain_centre(geo, d, xm, ym)
            if (.not. in_range(xm, ym, range)) cycle
         end if
         write (text, '(i8,a,i6,l6,i9)') d, fmt_real(geo%domains%area(d)), n, geo%domains%outer(d), &
            geo%domains%addr(d)
         call print_ring(out, text, 46, 6, geo%domains%ring(f:f + n - 1))
      end do
   end subroutine print_domains

   !> The contacts `ring` of a domain ten to a line, from column `col` in
   !> fields of `width`; the first line continues `text` (the domain's
   !> columns), the others are blank before `col`. A domain without
   !> contacts prints `text` alone.
   subroutine print_ring(out, text, col, width, ring)
      type(output_t), intent(in) :: out
      character(len=*), intent(inout) :: text
      integer, intent(in) :: col, width
      integer(ip), intent(in) :: ring(:)
      character(len=16) :: form
      integer :: k, n
      n = size(ring)
      write (form, '(a,i0,a)') '(10i', width, ')'
      do k = 0, n - 1, 10
         if (k > 0) text = ''
         write (text(col:), form) ring(k + 1:min(n, k + 10))
         call out%line(text)
      end do
      if (n == 0) call out%line(text)
   end subroutine print_ring

   !> PRINT DLIST: the domain list, each domain with its contacts in order
   !> (ten per line).
   subroutine print_domain_list(geo, out)
      type(geometry_t), intent(in) :: geo
      type(output_t), intent(in) :: out
      character(len=100) :: text
      integer(ip) :: d, f, n
      call out%line('  DOMAIN  CONTACTS (in order around the domain)')
      do d = 1, geo%domains%n
         if (.not. geo%domains%live(d)) cycle
         f = geo%domains%first(d)
         n = geo%domains%count(d)
         text = ''
         write (text(1:8), '(i8)') d
         call print_ring(out, text, 9, 8, geo%domains%ring(f:f + n - 1))
      end do
   end subroutine print_domain_list

   !> PRINT LIST: the block list, each block with its clockwise corners.
   subroutine print_list(geo, out, range)
      type(geometry_t), intent(in) :: geo
      type(output_t), intent(in) :: out
      type(range_t), intent(in), optional :: range
      character(len=100) :: text
      integer(ip) :: b, c, k, col
      call out%line('   BLOCK  CORNERS (clockwise)')
      do b = 1, geo%blocks%n
         if (.not. block_selected(geo, b, range)) cycle
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
