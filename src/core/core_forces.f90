!> Point-force application, one kernel for every stage that puts a force into
!> the force sums of the cycle (contacts, boundary points, far field,
!> dashpots, fluid pressures, structural interfaces): a rigid block takes the
!> force and its moment about the centroid; a deformable (FDEF) block's edge
!> shares it between the edge's two gridpoints. Callers subtract a reaction
!> by passing (-fx, -fy): negation is exact, so the sums are those of the
!> subtraction to the last bit.
module core_forces
   use core_kinds, only: wp, ip
   implicit none
   private
   public :: add_rigid_force, add_shared_force, add_sdef_moments

contains

   !> Force (fx, fy) at offset (rx, ry) from the centroid of block b into the
   !> block force sums (sum_x, sum_y, sum_m)(b).
   pure subroutine add_rigid_force(sum_x, sum_y, sum_m, b, rx, ry, fx, fy)
      real(wp), intent(inout) :: sum_x(:), sum_y(:), sum_m(:)
      integer(ip), intent(in) :: b
      real(wp), intent(in) :: rx, ry, fx, fy
      sum_x(b) = sum_x(b) + fx
      sum_y(b) = sum_y(b) + fy
      sum_m(b) = sum_m(b) + (rx*fy - ry*fx)
   end subroutine add_rigid_force

   !> Force (fx, fy) at offset (rx, ry) from the centroid of simply-deformable
   !> block b into its first-moment sums (the applied stress times area that
   !> drives its strain modes): qxx += fx rx, qyy += fy ry,
   !> qxy += (fx ry + fy rx) / 2.
   pure subroutine add_sdef_moments(qxx, qyy, qxy, b, rx, ry, fx, fy)
      real(wp), intent(inout) :: qxx(:), qyy(:), qxy(:)
      integer(ip), intent(in) :: b
      real(wp), intent(in) :: rx, ry, fx, fy
      qxx(b) = qxx(b) + fx*rx
      qyy(b) = qyy(b) + fy*ry
      qxy(b) = qxy(b) + 0.5_wp*(fx*ry + fy*rx)
   end subroutine add_sdef_moments

   !> Force (fx, fy) at fraction w along the edge from gridpoint a to b into
   !> the gridpoint force sums: (1 - w) of it to a, w to b (a = b, w = 0 at
   !> a corner).
   pure subroutine add_shared_force(sum_x, sum_y, a, b, w, fx, fy)
      real(wp), intent(inout) :: sum_x(:), sum_y(:)
      integer(ip), intent(in) :: a, b
      real(wp), intent(in) :: w, fx, fy
      sum_x(a) = sum_x(a) + (1.0_wp - w)*fx
      sum_y(a) = sum_y(a) + (1.0_wp - w)*fy
      sum_x(b) = sum_x(b) + w*fx
      sum_y(b) = sum_y(b) + w*fy
   end subroutine add_shared_force

end module core_forces
