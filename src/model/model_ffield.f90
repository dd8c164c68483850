!> The dynamic free field (manual Section 3.8.2, Eqs. 31-36; Section 4.5
!> FFIELD and BOUNDARY FF): a one-dimensional column of unit width between
!> y = yl and y = yu, np gridpoints at equal spacing dy and np - 1 zones of
!> uniform strain and stress, computed in parallel with the blocks
!> (zones_ffield). Its velocities and stresses drive the lateral boundary
!> points flagged by BOUNDARY FF (`boundary_t%ff`).
!>
!> Gridpoint i is at y(i) = yl + (i - 1) dy; zone i lies between gridpoints i
!> and i + 1. Stresses are tension positive, as in the zones; szz is the
!> plane-strain out-of-plane stress the Mohr-Coulomb test uses.
!>
!> `sxx0`, `sxy0` are the stresses saved by FFIELD INITIALIZE: they are
!> subtracted from the column's stresses before these are applied to the
!> blocks (the in-situ state is held by the reactions stored when the
!> lateral velocities were replaced by viscous conditions).
!>
!> The base (gridpoint 1): per direction a condition code (ff_free,
!> ff_stress, ff_velocity), a velocity, a stress (SXX: the normal stress syy
!> on the base, SXY the shear stress), a viscous flag, the force stored
!> when a viscous condition replaced a velocity (the support's reaction),
!> and the history (bh_* of model_boundary) captured from the last BOUNDARY
!> history keyword when FFIELD SXX / SXY is given.
module model_ffield
   use core_kinds, only: wp, ip
   use model_zones, only: zone_list_t, zones_add_zone
   implicit none
   private
   public :: ffield_t, ffield_generate, ffield_zone_at
   public :: ff_free, ff_stress, ff_velocity

   integer, parameter :: ff_free = 0, ff_stress = 1, ff_velocity = 4

   type :: ffield_t
      logical :: on = .false.                   !< FFIELD ON / OFF (GEN switches it on)
      integer(ip) :: np = 0                     !< gridpoints (0: no free field)
      real(wp) :: yl = 0.0_wp, yu = 0.0_wp, dy = 0.0_wp
      real(wp), allocatable :: vx(:), vy(:)     !< (np) velocities
      real(wp), allocatable :: ux(:), uy(:)     !< (np) displacements
      real(wp), allocatable :: fx(:), fy(:)     !< (np) force sums of the last step
      integer, allocatable :: mat(:), cons(:)   !< (np - 1) material, constitutive model
      !> (np - 1) zones: stresses sxx sxy syy szz and plasticity state, kept
      !> as a zone list so that the zones' constitutive kernels update them
      !> (vertices g1..g3 unused: 0)
      type(zone_list_t) :: zn
      real(wp), allocatable :: sxx0(:), sxy0(:) !< (np - 1) stresses saved by INITIALIZE
      !> base conditions, index 1 x, 2 y
      integer :: base_code(2) = ff_free
      logical :: base_visc(2) = .false.
      real(wp) :: base_v(2) = 0.0_wp            !< prescribed velocity
      real(wp) :: base_s(2) = 0.0_wp            !< SXY (x), SXX (y: normal stress on the base)
      real(wp) :: base_f(2) = 0.0_wp            !< reaction stored at a velocity -> viscous switch
      integer :: base_h = 0                     !< history type (bh_*)
      real(wp) :: base_freq = 0.0_wp, base_tload = 0.0_wp
   end type ffield_t

contains

   !> FFIELD GEN yl yu np: a new column at rest, zero stress, material 1,
   !> elastic, base free, switched on.
   subroutine ffield_generate(ff, yl, yu, np)
      type(ffield_t), intent(inout) :: ff
      real(wp), intent(in) :: yl, yu
      integer(ip), intent(in) :: np
      integer(ip) :: nz, k, id
      ff = ffield_t()
      ff%np = np
      ff%yl = yl
      ff%yu = yu
      ff%dy = (yu - yl)/real(np - 1, wp)
      nz = np - 1
      allocate (ff%vx(np), ff%vy(np), ff%ux(np), ff%uy(np), ff%fx(np), ff%fy(np))
      ff%vx = 0.0_wp; ff%vy = 0.0_wp; ff%ux = 0.0_wp; ff%uy = 0.0_wp
      ff%fx = 0.0_wp; ff%fy = 0.0_wp
      allocate (ff%mat(nz), ff%cons(nz), ff%sxx0(nz), ff%sxy0(nz))
      ff%mat = 1
      ff%cons = 1
      ff%sxx0 = 0.0_wp; ff%sxy0 = 0.0_wp
      do k = 1, nz
         call zones_add_zone(ff%zn, 0_ip, 0_ip, 0_ip, 0_ip, id)
      end do
      ff%on = .true.
   end subroutine ffield_generate

   !> The zone that holds height y (the end zones beyond the column).
   pure integer(ip) function ffield_zone_at(ff, y) result(k)
      type(ffield_t), intent(in) :: ff
      real(wp), intent(in) :: y
      real(wp) :: u
      u = (y - ff%yl)/ff%dy
      if (u < 0.0_wp) then
         k = 1
      else if (u >= real(ff%np - 1, wp)) then
         k = ff%np - 1
      else
         k = int(u, ip) + 1
      end if
   end function ffield_zone_at

end module model_ffield
