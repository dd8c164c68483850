!> Compatibility table for the 1989 addresses printed in the manual's
!> Appendix B decks that this program's layout does not reproduce (UDEC
!> manual (ICG1.5, 1989), Appendix B, Problems D and G; the search for the
!> 1989 numbering rule is in the case READMEs). Each row is one printed
!> address, the kind of entity the manual names with it, the outline of
!> the printed model (the box of its block corners) and the place the
!> manual's own text, deck comment or figure gives for that entity. The
!> rule: a command naming a row's address in a model with that outline,
!> where no entity of that kind has the address here, takes the entity of
!> that kind nearest the row's place (within the row's distance; outer
!> domains excluded) and says so in a note naming the source. Nothing else
!> is matched: another model, another address, or no entity near the place
!> leaves the command to the ordinary address rules.
module model_address_compat
   use core_kinds, only: wp, ip
   use model_geometry, only: geometry_t
   use model_address, only: ak_contact, ak_domain, address_entity, domain_centre
   implicit none
   private
   public :: compat_lookup

   type :: compat_row_t
      integer(ip) :: address
      integer :: kind
      real(wp) :: box(4)          !< xmin xmax ymin ymax of the printed model's corners
      real(wp) :: px, py, reach   !< the manual's place and how far from it (m)
      character(len=160) :: source
   end type compat_row_t

   !> Problem D: the dam (-40,0) (-40,100) (40,0) on the foundation -200..200 x
   !> -200..0. Problem G: the 10 m square 0..10 x 0..10.
   type(compat_row_t), parameter :: rows(3) = [ &
      compat_row_t(3445_ip, ak_contact, [-200.0_wp, 200.0_wp, -200.0_wp, 100.0_wp], &
                   -33.42_wp, -30.47_wp, 1.0_wp, &
                   'Appendix B Problem D, deck comment "contact 3445 is at x=-33.42 '// &
                   'y=-30.47" (Fig. D-1)'), &
      compat_row_t(4358_ip, ak_domain, [-200.0_wp, 200.0_wp, -200.0_wp, 100.0_wp], &
                   -22.0_wp, -26.0_wp, 2.0_wp, &
                   'Appendix B Problem D, Fig. D-5 "Domain 4358 Next to Contact 3445", '// &
                   'deck comment "x=-22,-26"'), &
      compat_row_t(697_ip, ak_domain, [0.0_wp, 10.0_wp, 0.0_wp, 10.0_wp], &
                   5.0_wp, 5.0_wp, 0.1_wp, &
                   'Appendix B Problem G, deck comment "pressurize hole (domain 697)": '// &
                   'the hole centred at (5,5)')]
   !> The outline matches when each side is within this fraction of the
   !> model's width of the row's (displacements of a run move the corners).
   real(wp), parameter :: outline_tol = 2.0e-3_wp

contains

   !> The entity named by printed address `a` under the table (kind 0,
   !> id 0: no row applies). `wanted` 0: any kind (HISTORY ADDRESS), else
   !> only rows of that kind. `source`: the row's reference for the note.
   subroutine compat_lookup(geo, a, wanted, kind, id, source)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: a
      integer, intent(in) :: wanted
      integer, intent(out) :: kind
      integer(ip), intent(out) :: id
      character(len=:), allocatable, intent(out) :: source
      integer :: r
      kind = 0
      id = 0
      source = ''
      do r = 1, size(rows)
         if (rows(r)%address /= a) cycle
         if (wanted /= 0 .and. rows(r)%kind /= wanted) cycle
         if (address_entity(geo, rows(r)%kind, a) > 0) cycle
         if (.not. outline_matches(geo, rows(r)%box)) cycle
         id = nearest(geo, rows(r))
         if (id == 0) cycle
         kind = rows(r)%kind
         source = trim(rows(r)%source)
         return
      end do
   end subroutine compat_lookup

   logical function outline_matches(geo, box) result(ok)
      type(geometry_t), intent(in) :: geo
      real(wp), intent(in) :: box(4)
      real(wp) :: lo(2), hi(2), tol
      integer(ip) :: i
      logical :: any
      lo = huge(1.0_wp)
      hi = -huge(1.0_wp)
      any = .false.
      do i = 1, geo%corners%n
         if (.not. geo%corners%live(i)) cycle
         any = .true.
         lo = min(lo, [geo%corners%x(i), geo%corners%y(i)])
         hi = max(hi, [geo%corners%x(i), geo%corners%y(i)])
      end do
      tol = outline_tol*max(box(2) - box(1), box(4) - box(3))
      ok = any .and. abs(lo(1) - box(1)) <= tol .and. abs(hi(1) - box(2)) <= tol .and. &
           abs(lo(2) - box(3)) <= tol .and. abs(hi(2) - box(4)) <= tol
   end function outline_matches

   !> The live entity of the row's kind nearest its place, within its reach
   !> (domains: by centre, the outer domain excluded); 0 if none.
   integer(ip) function nearest(geo, row) result(id)
      type(geometry_t), intent(in) :: geo
      type(compat_row_t), intent(in) :: row
      integer(ip) :: i
      real(wp) :: best, d, x, y
      id = 0
      best = nextafter_reach(row%reach)
      select case (row%kind)
      case (ak_contact)
         do i = 1, geo%contacts%n
            if (.not. geo%contacts%live(i)) cycle
            d = hypot(geo%contacts%x(i) - row%px, geo%contacts%y(i) - row%py)
            if (d < best) then
               best = d
               id = i
            end if
         end do
      case (ak_domain)
         do i = 1, geo%domains%n
            if (.not. geo%domains%live(i) .or. geo%domains%outer(i)) cycle
            call domain_centre(geo, i, x, y)
            d = hypot(x - row%px, y - row%py)
            if (d < best) then
               best = d
               id = i
            end if
         end do
      end select
   end function nearest

   !> The reach itself counts as within it (strict < above keeps the first
   !> of equally near entities, the lowest id).
   pure real(wp) function nextafter_reach(r) result(b)
      real(wp), intent(in) :: r
      b = r*(1.0_wp + 1.0e-12_wp)
   end function nextafter_reach

end module model_address_compat
