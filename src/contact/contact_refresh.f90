!> One call for command handlers after geometry commands: bring contacts
!> (UPCON) and domains (UPDOM) up to date when blocks changed since. Before
!> the first cycle contacts are rebuilt from scratch; once cycling has begun
!> they carry forces and are updated in place (contact_update).
module contact_refresh
   use core_kinds, only: ip, wp
   use model_geometry, only: geometry_t, geometry_release_slack
   use contact_detection, only: contact_rebuild
   use contact_domains, only: domain_rebuild
   use contact_update, only: contact_scan, contact_margin
   use geometry_blocks, only: geometry_round_facing
   implicit none
   private
   public :: geometry_refresh

contains

   !> Rebuild contacts and domains if any block changed since the last
   !> rebuild; `force` rebuilds regardless (UPCON / UPDOM). `searched`: the
   !> contacts carried forces and were updated in place with a search for
   !> new ones over the whole model at the contact margin, as the CYCLE's
   !> opening scan makes (its caller may record it: engine_cycle's
   !> search_done, so the CYCLE does not search again).
   !> `since` (> 0; the caller's word, engine_cycle search_base): the last
   !> search over the whole model still stands but for what the commands
   !> since made -- they cut, deleted or re-ringed blocks and nothing else,
   !> the corners they made have ids above `since`, and no block has
   !> travelled a quarter of the margin since. The search of a cycled model
   !> then looks only at the pairs with a changed block (contact_scan's
   !> `changed`), as the CYCLE's skipped search does for the unchanged ones.
   subroutine geometry_refresh(geo, force, searched, since)
      type(geometry_t), intent(inout) :: geo
      logical, intent(in), optional :: force
      logical, intent(out), optional :: searched
      integer(ip), intent(in), optional :: since
      logical :: all
      integer(ip) :: nnew, nbroken, base
      logical, allocatable :: changed(:)
      real(wp), allocatable :: radius(:)
      all = .false.
      if (present(force)) all = force
      if (present(searched)) searched = .false.
      base = 0
      if (present(since)) base = min(max(since, 0_ip), geo%corners%n)
      if (all) base = 0
      if (geo%mechanical) then
         ! contacts carry forces: update them in place (new, broken, lengths)
         if (all .or. .not. geo%contacts_valid) then
            ! blocks changed: corners facing across a short stretch
            ! (geometry_round_facing)
            if (base > 0) radius = geo%corners%radius(1:base)
            call geometry_round_facing(geo)
            if (base > 0) then
               call changed_blocks(geo, base, radius, changed)
               call contact_scan(geo, contact_margin(geo), nnew, nbroken, changed=changed)
            else
               call contact_scan(geo, contact_margin(geo), nnew, nbroken)
            end if
            geo%contacts_valid = .true.
            if (present(searched)) searched = .true.
         end if
      else if (all .or. .not. geo%contacts_valid) then
         ! the cutting commands leave the block and corner lists up to a
         ! fifth empty (list_capacity): give that back before the contact
         ! list grows, and the contact list's after it has
         call geometry_release_slack(geo, 1)
         call contact_rebuild(geo)
         call geometry_release_slack(geo, 2)
      end if
      if (all .or. .not. geo%domains_valid) call domain_rebuild(geo)
   end subroutine geometry_refresh

   !> The blocks a search after a cut must look at: a live block with a
   !> corner above `base` (a ring the cut made: geometry_set_block_polygon
   !> appends every new ring) or a corner whose rounding changed from
   !> `radius` (its value at the last search; geometry_round_facing caps a
   !> corner that now faces a new one).
   subroutine changed_blocks(geo, base, radius, changed)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: base
      real(wp), intent(in) :: radius(:)
      logical, allocatable, intent(out) :: changed(:)
      integer(ip) :: b, c
      allocate (changed(geo%blocks%n))
      changed = .false.
      do c = 1, geo%corners%n
         if (.not. geo%corners%live(c)) cycle
         b = geo%corners%block(c)
         if (c > base) then
            changed(b) = .true.
         else if (geo%corners%radius(c) /= radius(c)) then
            changed(b) = .true.
         end if
      end do
   end subroutine changed_blocks

end module contact_refresh
