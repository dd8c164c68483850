!> One call for command handlers after geometry commands: bring contacts
!> (UPCON) and domains (UPDOM) up to date when blocks changed since.
module contact_refresh
   use model_geometry, only: geometry_t
   use contact_detection, only: contact_rebuild
   use contact_domains, only: domain_rebuild
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
      all = .false.
      if (present(force)) all = force
      if (all .or. .not. geo%contacts_valid) call contact_rebuild(geo)
      if (all .or. .not. geo%domains_valid) call domain_rebuild(geo)
   end subroutine geometry_refresh

end module contact_refresh
