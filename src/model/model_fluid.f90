!> Joint fluid flow state (manual Section 3.12; FLUID, PFIX, PFREE, BOUNDARY
!> PP / PGRAD / IMPERMEABLE, SET CAPRATIO / SFLOW / EFF / YWTABLE / PTOL).
!>
!> An allocatable component of model_t: it exists once a fluid command has
!> been given, and a model without it runs no fluid code.
!>
!> Per domain (ids of geometry%domains): pressure p, fixed flag and the
!> domain's position (mean of its ring's contact points) and fluid volume of
!> the last step. Per contact (ids of geometry%contacts): hydraulic aperture
!> and flow rate of the last step (from side 1 to side 2; PRINT FLOWS), and
!> the boundary condition of a contact on the outer domain (bnd_code: 0 open
!> to a reservoir at pressure 0, 1 reservoir at pressure bnd_p + bnd_g y at
!> the contact point, 2 impermeable).
module model_fluid
   use core_kinds, only: wp, ip
   use core_arrays, only: grow_array, grow_lists
   implicit none
   private
   public :: fluid_t, fluid_size, bnd_open, bnd_pressure, bnd_impermeable

   integer, parameter :: bnd_open = 0, bnd_pressure = 1, bnd_impermeable = 2

   type :: fluid_t
      ! FLUID
      real(wp) :: rhow = 0.0_wp        !< fluid density [mass/volume]
      real(wp) :: bulkw = 0.0_wp       !< fluid bulk modulus [stress]; 0: no flow
      real(wp) :: cohw = 0.0_wp        !< yield strength (Bingham; kept, not used)
      ! SET
      real(wp) :: capratio = 5.0_wp    !< a_max = capratio * max ARES
      logical :: sflow = .false.       !< SET SFLOW: steady-state algorithm
      logical :: eff = .true.          !< SET EFF (default) / -EFF (total pressures)
      real(wp) :: ywtab = 1.0e20_wp    !< SET YWTABLE
      real(wp) :: ptol = 0.01_wp       !< SET PTOL: pressure change that triggers mechanics
      logical :: ptol_noted = .false.  !< CYCLE said PTOL is far below the pressures (not saved)
      ! domains
      integer(ip) :: nd = 0
      real(wp), allocatable :: p(:)          !< domain pressure
      logical, allocatable :: fixed(:)       !< PFIX
      real(wp), allocatable :: vol(:)        !< fluid volume of the last step
      real(wp), allocatable :: xd(:), yd(:)  !< domain position
      ! contacts
      integer(ip) :: nc = 0
      real(wp), allocatable :: aperture(:)   !< hydraulic aperture of the last step
      real(wp), allocatable :: q(:)          !< flow rate, side 1 -> side 2
      integer(ip), allocatable :: bnd_code(:)    !< bnd_open / bnd_pressure / bnd_impermeable
      real(wp), allocatable :: bnd_p(:)      !< reservoir pressure at y = 0 (bnd_pressure)
      real(wp), allocatable :: bnd_g(:)      !< its y-gradient (PGRAD): p = bnd_p + bnd_g y
      !> domains of each contact's sides when the pressures were last matched
      !> to the domains (0: outer): a rebuild since then is detected and the
      !> pressures are carried over through the contacts (fluid_sync)
      integer(ip), allocatable :: cdom1(:), cdom2(:)
   end type fluid_t

contains

   !> Make room for nd domains and nc contacts (new entries: pressure 0, free,
   !> open boundary).
   subroutine fluid_size(f, nd, nc)
      type(fluid_t), intent(inout) :: f
      integer(ip), intent(in) :: nd, nc
      integer(ip) :: m
      if (.not. allocated(f%p)) then
         allocate (f%p(0), f%fixed(0), f%vol(0), f%xd(0), f%yd(0))
         allocate (f%aperture(0), f%q(0), f%bnd_code(0), f%bnd_p(0), f%bnd_g(0), f%cdom1(0), f%cdom2(0))
      end if
      if (nd > size(f%p)) then
         m = max(nd, 2_ip*size(f%p))
         call grow_lists(f%nd, m, f%p, f%vol, f%xd, f%yd)
         call grow_array(f%fixed, f%nd, m)
      end if
      if (nd > f%nd) then
         f%p(f%nd + 1:nd) = 0.0_wp
         f%fixed(f%nd + 1:nd) = .false.
         f%vol(f%nd + 1:nd) = 0.0_wp
         f%xd(f%nd + 1:nd) = 0.0_wp
         f%yd(f%nd + 1:nd) = 0.0_wp
      end if
      f%nd = nd
      if (nc > size(f%q)) then
         m = max(nc, 2_ip*size(f%q))
         call grow_lists(f%nc, m, f%aperture, f%q, f%bnd_p, f%bnd_g)
         call grow_lists(f%nc, m, f%bnd_code, f%cdom1, f%cdom2)
      end if
      if (nc > f%nc) then
         f%aperture(f%nc + 1:nc) = 0.0_wp
         f%q(f%nc + 1:nc) = 0.0_wp
         f%bnd_code(f%nc + 1:nc) = bnd_open
         f%bnd_p(f%nc + 1:nc) = 0.0_wp
         f%bnd_g(f%nc + 1:nc) = 0.0_wp
         f%cdom1(f%nc + 1:nc) = -1
         f%cdom2(f%nc + 1:nc) = -1
      end if
      f%nc = nc
   end subroutine fluid_size

end module model_fluid
