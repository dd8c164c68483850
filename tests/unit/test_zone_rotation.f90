!> ROTATE ZONE (plot_profiles%zone_rotation): the rotation of a zone is
!> 0.5 (d uy/dx - d ux/dy) of its gridpoint displacements, exact for the
!> linear field of a triangle. Closed forms: a small rigid rotation by theta,
!> u = theta (-y, x), gives theta; a pure shear u = g (y, x) gives 0; a simple
!> shear u = (g y, 0) gives -g/2 (in degrees, counter-clockwise positive).
program test_zone_rotation
   use core_kinds, only: wp, ip
   use core_constants, only: pi
   use testing, only: check_close, testing_finish
   use model_geometry, only: geometry_t
   use model_zones, only: zones_add_gridpoint, zones_add_zone
   use plot_profiles, only: zone_rotation
   implicit none
   type(geometry_t) :: geo
   integer(ip) :: g(3), z
   real(wp), parameter :: xs(3) = [0.3_wp, 2.1_wp, 0.7_wp], ys(3) = [-0.4_wp, 0.2_wp, 1.9_wp]
   real(wp), parameter :: theta = 1.0e-3_wp, gam = 2.0e-3_wp, deg = 180.0_wp/pi
   integer :: i
   do i = 1, 3
      call zones_add_gridpoint(geo%gridpoints, 1_ip, 0_ip, xs(i), ys(i), g(i))
   end do
   call zones_add_zone(geo%zones, 1_ip, g(1), g(2), g(3), z)
   ! rigid rotation (small): u = theta (-y, x)
   geo%gridpoints%ux(g) = -theta*ys
   geo%gridpoints%uy(g) = theta*xs
   call check_close(zone_rotation(geo, z), theta*deg, 1.0e-12_wp, 'rigid rotation: theta')
   ! a rigid translation added changes nothing
   geo%gridpoints%ux(g) = geo%gridpoints%ux(g) + 0.5_wp
   geo%gridpoints%uy(g) = geo%gridpoints%uy(g) - 0.25_wp
   call check_close(zone_rotation(geo, z), theta*deg, 1.0e-9_wp, 'rotation + translation: theta')
   ! pure shear: no rotation
   geo%gridpoints%ux(g) = gam*ys
   geo%gridpoints%uy(g) = gam*xs
   call check_close(zone_rotation(geo, z), 0.0_wp, 1.0e-12_wp, 'pure shear: 0')
   ! simple shear u = (g y, 0): rotation -g/2
   geo%gridpoints%ux(g) = gam*ys
   geo%gridpoints%uy(g) = 0.0_wp
   call check_close(zone_rotation(geo, z), -0.5_wp*gam*deg, 1.0e-12_wp, 'simple shear: -g/2')
   call testing_finish()
end program test_zone_rotation
