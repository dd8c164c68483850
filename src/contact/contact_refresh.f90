!> One call for command handlers after geometry commands: bring contacts
!> (UPCON) and domains (UPDOM) up to date when blocks changed since. Before
!> the first cycle contacts are rebuilt from scratch; once cycling has begun
!> they carry forces and are updated in place (contact_update).
module contact_refresh
   use core_kinds, only: ip
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
   !> rebuild; `force` rebuilds regardless (UPCON / UPDOM).
   subroutine geometry_refresh(geo, force)
      type(geometry_t), intent(inout) :: geo
      logical, intent(in), optional :: force
      logical :: all
      integer(ip) :: nnew, nbroken
      all = .false.
      if (present(force)) all = force
      if (geo%mechanical) then
         ! contacts carry forces: update them in place (new, broken, lengths)
         if (all .or. .not. geo%contacts_valid) then
            ! blocks changed: corners facing across a short stretch
            ! (geometry_round_facing)
            call geometry_round_facing(geo)
            call contact_scan(geo, contact_margin(geo), nnew, nbroken)
            geo%contacts_valid = .true.
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

end module contact_refresh
