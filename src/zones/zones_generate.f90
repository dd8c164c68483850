!> Putting a zoning (zones_mesh) into the model: the block's new boundary
!> ring becomes its corner ring, every corner gets a gridpoint, interior
!> points get gridpoints with corner 0, zones are appended, and the block
!> becomes fully deformable (manual Sections 3.2 and 4.5 GENERATE).
module zones_generate
   use core_kinds, only: wp, ip
   use model_geometry, only: geometry_t, geometry_block_polygon
   use geometry_blocks, only: geometry_set_block_polygon
   use model_zones, only: zones_add_gridpoint, zones_add_zone
   use zones_mesh, only: mesh_t
   implicit none
   private
   public :: zones_apply_mesh

contains

   !> Zone block `b` with `mesh`, whose boundary ring starts at the block's
   !> first corner and runs clockwise. Boundary points that are not corners
   !> become corners on the edges: the ring is rebuilt (new corner ids, new
   !> rounding; straight corners are not rounded). The block must not be
   !> zoned yet (the caller checks).
   subroutine zones_apply_mesh(geo, b, mesh)
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: b
      type(mesh_t), intent(in) :: mesh
      real(wp), allocatable :: x(:), y(:)
      integer(ip), allocatable :: ids(:)
      integer(ip) :: k, id, g0, z0, corner
      if (mesh%nb /= geo%blocks%ncorner(b)) then
         call geometry_set_block_polygon(geo, b, mesh%x(1:mesh%nb), mesh%y(1:mesh%nb))
      end if
      call geometry_block_polygon(geo, b, x, y, ids)
      g0 = geo%gridpoints%n + 1
      do k = 1, mesh%np
         corner = 0
         if (k <= mesh%nb) corner = ids(k)
         call zones_add_gridpoint(geo%gridpoints, b, corner, mesh%x(k), mesh%y(k), id)
         if (corner > 0) geo%corners%gp(corner) = id
      end do
      z0 = geo%zones%n + 1
      do k = 1, mesh%nt
         call zones_add_zone(geo%zones, b, g0 - 1 + mesh%tri(1, k), g0 - 1 + mesh%tri(2, k), &
                             g0 - 1 + mesh%tri(3, k), id)
      end do
      geo%blocks%fdef(b) = .true.
      geo%blocks%sdef(b) = .false.      ! a zoned block is no longer simply deformable
      geo%blocks%gfirst(b) = g0
      geo%blocks%ngp(b) = mesh%np
      geo%blocks%zfirst(b) = z0
      geo%blocks%nzone(b) = mesh%nt
   end subroutine zones_apply_mesh

end module zones_generate
