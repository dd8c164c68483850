!> Mechanics of fully-deformable blocks (manual Sections 3.2 and 3.5): lumped
!> gridpoint masses, the zone time step, strain increments, stresses and
!> gridpoint forces of constant-strain triangles, and the gridpoint
!> equations of motion (Eq. 1, central differences as Eq. 24/25 with the
!> viscous damping of Eq. 28).
!>
!> Triangle with counter-clockwise vertices k = 1, 2, 3 and area A:
!>   dN_k/dx = (y_{k+1} - y_{k+2}) / 2A,  dN_k/dy = (x_{k+2} - x_{k+1}) / 2A
!>   strain rates from gridpoint velocities, d eps = sym(grad v) dt,
!>   rotation d theta = (dv_y/dx - dv_x/dy)/2 dt turns the old stresses
!>   (sxx -= 2 sxy dth, syy += 2 sxy dth, sxy += (sxx - syy) dth), then the
!>   zone model adds the increments (zones_models);
!>   force on gridpoint k: F_i = -A sigma_ij dN_k/dx_j (= the integral of
!>   sigma n over the part of the zone boundary around k).
!> Geometry is updated every step (large displacements, Section 3.2).
!>
!> Masses: each zone gives rho A / 3 to each vertex (gridpoints%mass, the
!> real mass gravity acts on). The inertial mass differs under MSCALE:
!> ON zcmass gives every zone the mass zcmass (default: the average zone
!> mass); PART tdel raises only the gridpoint masses too small for tdel.
!>
!> Time step: Gershgorin's bound on the highest frequency of a gridpoint,
!> w^2 <= k_gp / m_gp with k_gp the absolute row sum of the stiffness
!> acting on it: zones A (K + 4G/3) (|dN_k/dx|+|dN_k/dy|) sum_j (|dN_j/dx|
!> + |dN_j/dy|), and for a gridpoint on a block edge the stiffest joint
!> (2 k_joint times half its two edges, or 2 KN for point contacts);
!> dt_zone = 2 min sqrt(m_gp / k_gp).
module zones_mechanics
   use core_kinds, only: wp, ip, l1
   use core_motion, only: motion_step_t, motion_result_t
   use core_union_find, only: union_find_join, union_find_root
   use model_properties, only: prop_jkn, prop_jks, prop_kn, prop_ks
   use core_error, only: error_t, set_error
   use core_output, only: format_real
   use model_geometry, only: geometry_t
   use model_materials, only: material_table_t
   use model_zones, only: vfix_x, vfix_y
   use zones_models, only: zone_props_t, zone_props_of, zone_model_t, zone_model_create, zone_groups, &
                           elastic_model_t, elastic_constants, elastic_zone
   use zones_mixed, only: zone_partners
   !$ use omp_lib, only: omp_get_max_threads
   implicit none
   private
   public :: zone_work_t, zones_prepare, zones_timestep, zones_stress_pass, zones_clear_forces
   public :: gridpoint_motion, zones_block_centroids, zones_present, zones_stiffness, stiffer_limit

   !> Growth of a zone's stiffness term (its shape) after which the
   !> gridpoint stiffness bounds and the time step are computed again
   real(wp), parameter :: stiffer_limit = 1.05_wp
   !> Fewer live zones than this run on one thread whatever OMP_NUM_THREADS
   !> says: below it the threads' start and join cost more than they save.
   !> Without OMP_NUM_THREADS in the environment the zone cycle runs on one
   !> thread (zones_prepare).
   integer(ip), parameter :: thread_min_zones = 4000

   type :: model_holder_t
      class(zone_model_t), allocatable :: model
   end type model_holder_t

   !> Workspace of the zone phase for one CYCLE command.
   type :: zone_work_t
      logical :: active = .false.            !< the model has zones
      real(wp), allocatable :: m_in(:)       !< inertial gridpoint mass
      real(wp), allocatable :: kgp(:)        !< stiffness bound per gridpoint
      ! groups: live zones sharing (cons, material), contiguous in gidx
      integer :: ngroup = 0
      integer, allocatable :: gcons(:), gmat(:), gstart(:)
      integer(ip), allocatable :: gidx(:)
      type(zone_props_t), allocatable :: gprops(:)
      type(model_holder_t) :: models(0:3)    !< by CONS number
      ! per-zone scratch (index into gidx order)
      real(wp), allocatable :: dxx(:), dyy(:), dxy(:)
      real(wp), allocatable :: bx(:, :), by(:, :)   !< dN_k/dx * A, dN_k/dy * A of the step
      real(wp), allocatable :: area2(:)              !< 2A of the step
      logical, allocatable :: mixed(:)               !< zone uses the mixed discretization
      logical :: any_mixed = .false.
      integer(ip), allocatable :: mate(:)            !< its partner (gidx order, 0: none; zones_mixed)
      !> group of the mixed average (gidx order, 0: none): the zones joined by
      !> mate links, a pair or a pair with its one-way leftovers (mixed_zones)
      integer(ip), allocatable :: mgroup(:)
      real(wp), allocatable :: msum(:), marea(:)     !< sums per group of the step
      real(wp), allocatable :: pev(:)                !< volumetric increment / mean stress increment of the step
      real(wp), allocatable :: pold(:)               !< in-plane mean stress before the model call (mixed zones)
      logical, allocatable :: still(:)               !< gridpoint of an excavated (CONS 0) block
      real(wp), allocatable :: kref(:, :)            !< vertex stiffness terms when kgp was computed
      !> a vertex stiffness term grew past stiffer_limit times its value
      !> when kgp was computed (zones_stress_pass; the cycle refreshes kgp)
      logical :: stiffer = .false.
      !> every group elastic and none mixed: zones_stress_pass runs
      !> elastic_stress_pass and the general work arrays are not allocated
      logical :: elastic_only = .false.
      !> every zone group's law is elastic (mixed discretisation or not): DAMP
      !> AUTO's probe after a load change (engine_cycle damping_probe) runs
      logical :: elastic_law = .false.
      !> threads of the zone and gridpoint passes (1 without OpenMP); with more
      !> than one, each group's zones are cut into nthreads chunks (gather_lists):
      !> a gridpoint whose zones all lie in one chunk takes its force terms from
      !> that chunk's thread directly; the terms of the others (shared) go to zs
      !> and one pass adds them in the one-thread order
      integer :: nthreads = 1
      logical(l1), allocatable :: gshared(:)         !< gridpoint's zones lie in more than one chunk
      integer(ip) :: nshared = 0                     !< shared gridpoints (sgp)
      integer(ip), allocatable :: cslot(:)           !< (chunks + 1): a chunk's first slot in zs
      !> (2, chunks): a chunk's longest run of zones that touch no shared gridpoint,
      !> which runs through the one-thread loop (no test per vertex)
      integer(ip), allocatable :: crun(:, :)
      real(wp), allocatable :: zs(:, :)              !< (2, slots): shared vertices' force terms of the step
      integer(ip), allocatable :: sgp(:)             !< the shared gridpoints, ascending
      integer(ip), allocatable :: sptr(:)            !< shared gridpoint j's slots: slist(sptr(j):sptr(j+1)-1)
      integer(ip), allocatable :: slist(:)           !< slots in the one-thread order (ascending zone, vertex)
      real(wp), allocatable :: gterm(:, :)           !< (5, gridpoints): |F|, kinetic, damping, probe terms
   end type zone_work_t

contains

   include 'core_damping.inc'

   !> True when some live block is fully deformable.
   pure logical function zones_present(geo)
      type(geometry_t), intent(in) :: geo
      zones_present = .false.
      if (geo%blocks%n > 0) zones_present = any(geo%blocks%fdef(1:geo%blocks%n) .and. &
                                                geo%blocks%live(1:geo%blocks%n))
   end function zones_present

   !> Groups, models, masses and stiffness bounds before a CYCLE. Errors: an
   !> FDEF block without zones, a zone material without density or moduli.
   subroutine zones_prepare(geo, mats, mscale, zcmass, mscale_part, tdel, frac_zone, work, error)
      type(geometry_t), intent(inout) :: geo
      type(material_table_t), intent(in) :: mats
      logical, intent(in) :: mscale, mscale_part
      real(wp), intent(in) :: zcmass, tdel, frac_zone
      type(zone_work_t), intent(inout) :: work
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: b, z, g1, g2, g3, k, nz, nlive, j
      integer :: g, ng, cons, mat, k32
      integer, allocatable :: zgroup(:), zcons(:), zmat(:)
      real(wp) :: area, x1, y1, x2, y2, x3, y3, rho, zm
      character(len=200) :: msg
      work%active = zones_present(geo)
      if (.not. work%active) return
      associate (bl => geo%blocks, gp => geo%gridpoints, zn => geo%zones, co => geo%corners)
         do b = 1, bl%n
            if (.not. (bl%live(b) .and. bl%fdef(b))) cycle
            if (bl%nzone(b) == 0) then
               write (msg, '(a,i0,a,a,a,a,a)') 'CYCLE: block ', b, ' (centroid ', format_real(bl%xc(b)), &
                  ', ', format_real(bl%yc(b)), ') is fully deformable but has no zones: give GENERATE for it'
               call set_error(error, trim(msg))
               return
            end if
         end do
         ! groups by (cons, material) of the live zones
         nz = zn%n
         allocate (zcons(nz), zmat(nz))
         zcons = 0
         zmat = 0
         do z = 1, nz
            if (.not. zn%live(z)) cycle
            zcons(z) = bl%cons(zn%block(z))
            zmat(z) = bl%material(zn%block(z))
         end do
         call zone_groups(zcons, zmat, zn%live(1:nz), zgroup, work%gcons, work%gmat, work%gstart, work%gidx)
         ng = size(work%gmat)
         work%ngroup = ng
         if (allocated(work%gprops)) deallocate (work%gprops)
         allocate (work%gprops(ng))
         do g = 1, ng
            cons = work%gcons(g)
            if (.not. allocated(work%models(min(max(cons, 0), 3))%model) .or. &
                .not. any(cons == [0, 1, 3])) then
               block
                  class(zone_model_t), allocatable :: m
                  call zone_model_create(cons, m, error)
                  if (allocated(error)) return
                  call move_alloc(m, work%models(cons)%model)
               end block
            end if
            mat = work%gmat(g)
            work%gprops(g) = zone_props_of(mats, mat)
            if (work%gprops(g)%density <= 0.0_wp) then
               write (msg, '(a,i0,a,i0,a)') 'CYCLE: zoned blocks of material ', mat, &
                  ' have no mass: give PROPERTY MAT=', mat, ' DENSITY=..'
               call set_error(error, trim(msg))
               return
            end if
            if (cons /= 0 .and. (work%gprops(g)%bulk <= 0.0_wp .or. work%gprops(g)%shear <= 0.0_wp)) then
               write (msg, '(a,i0,a,i0,a)') 'CYCLE: zoned blocks of material ', mat, &
                  ' need elastic moduli: give PROPERTY MAT=', mat, ' K=.. G=..'
               call set_error(error, trim(msg))
               return
            end if
         end do
         k = max(1_ip, size(work%gidx, kind=ip))
         if (allocated(work%dxx)) deallocate (work%dxx, work%dyy, work%dxy, work%bx, work%by, work%area2)
         call mixed_zones(geo, work)
         work%elastic_law = .true.
         do g = 1, ng
            select type (m => work%models(work%gcons(g))%model)
            type is (elastic_model_t)
            class default
               work%elastic_law = .false.
            end select
         end do
         work%elastic_only = work%elastic_law .and. .not. work%any_mixed
         ! work arrays of the general pass only (elastic_stress_pass needs none)
         if (.not. work%elastic_only) then
            allocate (work%dxx(k), work%dyy(k), work%dxy(k), work%bx(3, k), work%by(3, k), work%area2(k))
            if (.not. allocated(work%pev)) allocate (work%pev(k))
         end if
         ! threads only when asked for (OMP_NUM_THREADS set): on a machine
         ! shared with other work, threads that wait at each pass's barrier for
         ! a descheduled partner made a step 8 times slower (docs/performance.md)
         work%nthreads = 1
         call get_environment_variable('OMP_NUM_THREADS', status=k32)
         if (k32 == 0) then
            !$ work%nthreads = omp_get_max_threads()
         end if
         if (work%gstart(ng + 1) - 1 < thread_min_zones) work%nthreads = 1
         call gather_lists(geo, work)
         ! excavated blocks (CONS 0): their gridpoints stay where they are
         ! (no stress, no contact force, no gravity: see contact_groups_build)
         if (allocated(work%still)) deallocate (work%still)
         allocate (work%still(max(1_ip, gp%n)))
         work%still = .false.
         do k = 1, gp%n
            if (gp%live(k)) work%still(k) = bl%cons(gp%block(k)) == 0
         end do
         ! masses and stiffness bounds
         if (allocated(work%m_in)) deallocate (work%m_in, work%kgp)
         allocate (work%m_in(max(1_ip, gp%n)), work%kgp(max(1_ip, gp%n)))
         gp%mass(1:gp%n) = 0.0_wp
         work%m_in = 0.0_wp
         work%kgp = 0.0_wp
         zm = 0.0_wp
         nlive = 0
         do g = 1, ng
            rho = work%gprops(g)%density
            do j = work%gstart(g), work%gstart(g + 1) - 1
               z = work%gidx(j)
               g1 = zn%g1(z); g2 = zn%g2(z); g3 = zn%g3(z)
               x1 = gp%x(g1); y1 = gp%y(g1)
               x2 = gp%x(g2); y2 = gp%y(g2)
               x3 = gp%x(g3); y3 = gp%y(g3)
               area = 0.5_wp*((x2 - x1)*(y3 - y1) - (x3 - x1)*(y2 - y1))
               if (area <= 0.0_wp) then
                  write (msg, '(a,i0,a,a,a,a,a)') 'CYCLE: zone ', z, ' near (', &
                     format_real((x1 + x2 + x3)/3.0_wp), ', ', format_real((y1 + y2 + y3)/3.0_wp), &
                     ') has zero or negative area'
                  call set_error(error, trim(msg))
                  return
               end if
               gp%mass(g1) = gp%mass(g1) + rho*area/3.0_wp
               gp%mass(g2) = gp%mass(g2) + rho*area/3.0_wp
               gp%mass(g3) = gp%mass(g3) + rho*area/3.0_wp
               zm = zm + rho*area
               nlive = nlive + 1
            end do
         end do
         call zones_stiffness(geo, mats, work)
         work%m_in(1:gp%n) = gp%mass(1:gp%n)
         if (mscale .and. .not. mscale_part) then
            ! every zone gets zcmass (default: the average zone mass)
            if (zcmass > 0.0_wp) then
               zm = zcmass
            else if (nlive > 0) then
               zm = zm/real(nlive, wp)
            end if
            work%m_in = 0.0_wp
            do j = 1, work%gstart(ng + 1) - 1
               z = work%gidx(j)
               work%m_in(zn%g1(z)) = work%m_in(zn%g1(z)) + zm/3.0_wp
               work%m_in(zn%g2(z)) = work%m_in(zn%g2(z)) + zm/3.0_wp
               work%m_in(zn%g3(z)) = work%m_in(zn%g3(z)) + zm/3.0_wp
            end do
         else if (mscale .and. mscale_part .and. tdel > 0.0_wp) then
            ! partial density scaling: raise only the masses too small for tdel
            do k = 1, gp%n
               if (.not. gp%live(k)) cycle
               work%m_in(k) = max(work%m_in(k), work%kgp(k)*(0.5_wp*tdel/max(frac_zone, 1.0e-12_wp))**2)
            end do
         end if
      end associate
   end subroutine zones_prepare

   !> Stiffness bound of every gridpoint (module header: Gershgorin), from
   !> the current shape of the zones and the block edges, and each zone's
   !> vertex terms at this shape (work%kref, watched by zones_stress_pass:
   !> zones flattened by large strain stiffen their gridpoints, and the time
   !> step must follow, work%stiffer). Called by zones_prepare and again by
   !> the cycle when work%stiffer exceeds stiffer_limit.
   subroutine zones_stiffness(geo, mats, work)
      type(geometry_t), intent(in) :: geo
      type(material_table_t), intent(in) :: mats
      type(zone_work_t), intent(inout) :: work
      integer(ip) :: z, g1, g2, g3, k, j, i
      integer :: g
      real(wp) :: x1, y1, x2, y2, x3, y3, a2, sa(3), st, cmod, kjoint, kpoint, l1, l2
      associate (gp => geo%gridpoints, zn => geo%zones, co => geo%corners)
         if (allocated(work%kref)) then
            if (size(work%kref, 2) /= max(1_ip, size(work%gidx))) deallocate (work%kref)
         end if
         if (.not. allocated(work%kref)) allocate (work%kref(3, max(1_ip, size(work%gidx))))
         work%kref = 0.0_wp
         work%kgp(1:gp%n) = 0.0_wp
         do g = 1, work%ngroup
            cmod = work%gprops(g)%bulk + 4.0_wp*work%gprops(g)%shear/3.0_wp
            do i = work%gstart(g), work%gstart(g + 1) - 1
               z = work%gidx(i); g1 = zn%g1(z); g2 = zn%g2(z); g3 = zn%g3(z)
               x1 = gp%x(g1); y1 = gp%y(g1)
               x2 = gp%x(g2); y2 = gp%y(g2)
               x3 = gp%x(g3); y3 = gp%y(g3)
               a2 = (x2 - x1)*(y3 - y1) - (x3 - x1)*(y2 - y1)
               if (a2 <= 0.0_wp) cycle        ! refused by zones_prepare / the step
               ! |dN/dx| + |dN/dy| per vertex (times 2A)
               sa(1) = abs(y2 - y3) + abs(x3 - x2)
               sa(2) = abs(y3 - y1) + abs(x1 - x3)
               sa(3) = abs(y1 - y2) + abs(x2 - x1)
               st = sum(sa)
               work%kref(:, i) = sa*st/a2
               work%kgp(g1) = work%kgp(g1) + 0.5_wp*cmod*work%kref(1, i)
               work%kgp(g2) = work%kgp(g2) + 0.5_wp*cmod*work%kref(2, i)
               work%kgp(g3) = work%kgp(g3) + 0.5_wp*cmod*work%kref(3, i)
            end do
         end do
         ! joints acting on boundary gridpoints
         kjoint = 0.0_wp
         kpoint = 0.0_wp
         do j = 1, mats%nmat
            kjoint = max(kjoint, mats%get(j, prop_jkn), mats%get(j, prop_jks))
            kpoint = max(kpoint, mats%get(j, prop_kn), mats%get(j, prop_ks))
         end do
         do k = 1, gp%n
            if (.not. gp%live(k)) cycle
            j = gp%corner(k)
            if (j == 0) cycle
            l1 = hypot(co%x(co%next(j)) - co%x(j), co%y(co%next(j)) - co%y(j))
            l2 = hypot(co%x(co%prev(j)) - co%x(j), co%y(co%prev(j)) - co%y(j))
            work%kgp(k) = work%kgp(k) + max(2.0_wp*kjoint*0.5_wp*(l1 + l2), 2.0_wp*kpoint)
         end do
      end associate
      work%stiffer = .false.
   end subroutine zones_stiffness

   !> Critical time step of the gridpoints (without FRACTION fz); huge if
   !> nothing bounds it. `kextra` [stress/length]: a stiffness acting on the
   !> joints besides JKN / JKS (the fluid's Kw / a, manual Section 3.12),
   !> added at the block-boundary gridpoints as zones_stiffness adds the
   !> joints' (both sides of the joint, over the half edges on either side).
   real(wp) function zones_timestep(geo, work, kextra) result(dt)
      type(geometry_t), intent(in) :: geo
      type(zone_work_t), intent(in) :: work
      real(wp), intent(in), optional :: kextra
      integer(ip) :: k, j
      real(wp) :: kx, kk, l1, l2
      dt = huge(1.0_wp)
      if (.not. work%active) return
      kx = 0.0_wp
      if (present(kextra)) kx = kextra
      associate (co => geo%corners)
         do k = 1, geo%gridpoints%n
            if (.not. geo%gridpoints%live(k)) cycle
            if (geo%gridpoints%vfix(k) == ior(vfix_x, vfix_y)) cycle
            if (work%still(k)) cycle
            kk = work%kgp(k)
            j = geo%gridpoints%corner(k)
            if (kx > 0.0_wp .and. j /= 0) then
               l1 = hypot(co%x(co%next(j)) - co%x(j), co%y(co%next(j)) - co%y(j))
               l2 = hypot(co%x(co%prev(j)) - co%x(j), co%y(co%prev(j)) - co%y(j))
               kk = kk + 2.0_wp*kx*0.5_wp*(l1 + l2)
            end if
            if (kk <= 0.0_wp .or. work%m_in(k) <= 0.0_wp) cycle
            dt = min(dt, 2.0_wp*sqrt(work%m_in(k)/kk))
         end do
      end associate
   end function zones_timestep

   !> Force sums of gridpoints to zero (start of the force phase of a step).
   subroutine zones_clear_forces(geo)
      type(geometry_t), intent(inout) :: geo
      integer(ip) :: n
      n = geo%gridpoints%n
      if (n == 0) return
      geo%gridpoints%fx(1:n) = 0.0_wp
      geo%gridpoints%fy(1:n) = 0.0_wp
   end subroutine zones_clear_forces

   !> Which zones use the mixed discretization, and their partners: zones
   !> of plastic groups (CONS 3) in blocks that are not zoned in crossed
   !> quadrilaterals, each paired with a neighbour across an edge
   !> (zones_mixed; the 1989 zone word KZLL). A crossed quad (GENERATE QUAD:
   !> four triangles around a centre gridpoint) is free of volumetric locking
   !> by itself (Nagtegaal et al. 1974); averaging on top of it leaves too few
   !> constraints (verification D, Prandtl's footing on QUAD 1.15 1.0: -26 %
   !> with a nodal average, -4 % without). A block counts as crossed-quad
   !> zoned when each of its zones has an interior gridpoint shared by
   !> exactly four zones.
   subroutine mixed_zones(geo, work)
      type(geometry_t), intent(in) :: geo
      type(zone_work_t), intent(inout) :: work
      integer, allocatable :: degree(:)
      logical, allocatable :: crossed(:)
      integer(ip) :: i, z, b, k, gv(3), n
      integer(ip), allocatable :: v(:, :)
      integer :: g
      logical :: has
      if (allocated(work%mixed)) deallocate (work%mixed)
      if (allocated(work%mate)) deallocate (work%mate)
      if (allocated(work%mgroup)) deallocate (work%mgroup, work%msum, work%marea)
      if (allocated(work%pev)) deallocate (work%pev)
      if (allocated(work%pold)) deallocate (work%pold)
      work%any_mixed = .false.
      ! only plastic groups (CONS 3) can be mixed
      if (.not. any(work%gcons(1:work%ngroup) == 3)) return
      associate (gp => geo%gridpoints, zn => geo%zones, bl => geo%blocks)
         allocate (work%mixed(size(work%gidx)))
         work%mixed = .false.
         allocate (degree(max(1_ip, gp%n)), crossed(max(1_ip, bl%n)))
         degree = 0
         crossed = .true.
         do z = 1, zn%n
            if (.not. zn%live(z)) cycle
            degree(zn%g1(z)) = degree(zn%g1(z)) + 1
            degree(zn%g2(z)) = degree(zn%g2(z)) + 1
            degree(zn%g3(z)) = degree(zn%g3(z)) + 1
         end do
         do z = 1, zn%n
            if (.not. zn%live(z)) cycle
            gv = [zn%g1(z), zn%g2(z), zn%g3(z)]
            has = .false.
            do k = 1, 3
               if (gp%corner(gv(k)) == 0 .and. degree(gv(k)) == 4) has = .true.
            end do
            b = zn%block(z)
            if (.not. has) crossed(b) = .false.
         end do
         do g = 1, work%ngroup
            if (work%gcons(g) /= 3) cycle
            do i = work%gstart(g), work%gstart(g + 1) - 1
               work%mixed(i) = .not. crossed(zn%block(work%gidx(i)))
            end do
         end do
         allocate (work%mate(size(work%gidx)), work%pev(size(work%gidx)), work%pold(size(work%gidx)))
         work%mate = 0
         work%any_mixed = any(work%mixed)
         n = work%gstart(work%ngroup + 1) - 1
         allocate (v(3, max(1_ip, n)))
         do i = 1, n
            z = work%gidx(i)
            v(:, i) = [zn%g1(z), zn%g2(z), zn%g3(z)]
         end do
         if (n > 0) call zone_partners(v(:, 1:n), work%mixed(1:n), max(1_ip, gp%n), work%mate(1:n))
         call mixed_groups(work%mate, work%mgroup)
         allocate (work%msum(size(work%gidx)), work%marea(size(work%gidx)))
      end associate
   end subroutine mixed_zones

   !> Groups of the mixed average: the zones joined by mate links (union of
   !> the links, each group named by its smallest member), 0 for a zone
   !> without a link. A pair is a group of two; a leftover zone that points
   !> one way at a pair (zones_mixed) joins that pair's group.
   !>
   !> Why groups and not each zone's own pair: a leftover averaged with its
   !> neighbour's increment while the neighbour's pair ignored it makes the
   !> zones' stiffness unsymmetric (the leftover's forces follow the pair's
   !> gridpoints, the pair's do not follow the leftover's). That part of the
   !> stiffness does work over a cycle of motion: at the acute corner of a
   !> block where four blocks meet at a joint crossing (the guide's tunnel,
   !> docs/guide/tunnel.md) the corner gridpoint grew at 415 1/s at 1460 Hz
   !> with no damping, and DAMP AUTO held it at a steady rattle (5e-4 m/s),
   !> so SOLVE never reached its default ratio. The group mean is one
   !> symmetric constraint per group; a pair's mean is the same expression
   !> (and the same bits) as before.
   subroutine mixed_groups(mate, group)
      integer(ip), intent(in) :: mate(:)
      integer(ip), allocatable, intent(out) :: group(:)
      integer(ip), allocatable :: up(:)
      integer(ip) :: i, n
      n = size(mate)
      allocate (group(n), up(n))
      do i = 1, n
         up(i) = i
      end do
      do i = 1, n
         if (mate(i) > 0) call union_find_join(up, i, mate(i))
      end do
      do i = 1, n
         group(i) = 0
         if (mate(i) > 0) group(i) = union_find_root(up, i)
      end do
      ! a zone only pointed at (one way) belongs to the group too
      do i = 1, n
         if (mate(i) > 0) group(mate(i)) = group(i)
      end do
   end subroutine mixed_groups

   !> Strain increments, zone models, gridpoint forces (module header).
   !> Zones of plastic models (CONS 3) use the mixed discretization for
   !> volumetric strain increments (except crossed quads, see mixed_zones):
   !> each such zone takes the area-weighted mean volumetric increment of
   !> itself and its partner (deviatoric increments unchanged).
   !> Constant-strain triangles alone lock under incompressible plastic flow
   !> (the CONS 3 caution of the manual); with the averaging a uniform field
   !> is unchanged and collapse loads come down to the exact ones. Elastic
   !> zones keep the plain triangle (no locking at the Poisson's ratios of
   !> rock).
   subroutine zones_stress_pass(geo, work, dt)
      type(geometry_t), intent(inout) :: geo
      type(zone_work_t), intent(inout) :: work
      real(wp), intent(in) :: dt
      integer :: g
      integer(ip) :: i, i0, n, z, g1, g2, g3, ntot, j
      real(wp) :: x1, y1, x2, y2, x3, y3, a2, b1x, b2x, b3x, b1y, b2y, b3y
      real(wp) :: dvxdx, dvxdy, dvydx, dvydy, dth, sxx, syy, sxy, r, ev, evn, st, grow
      integer(ip) :: nback
      integer :: pass
      !> pairing / return alternations per step (see below)
      integer, parameter :: pair_passes = 1
      if (.not. work%active) return
      if (work%elastic_only) then
         call elastic_stress_pass(geo, work, dt)
         return
      end if
      associate (gp => geo%gridpoints, zn => geo%zones)
         ntot = work%gstart(work%ngroup + 1) - 1
         grow = -huge(1.0_wp)
         do i = 1, ntot
            z = work%gidx(i)
            g1 = zn%g1(z); g2 = zn%g2(z); g3 = zn%g3(z)
            x1 = gp%x(g1); y1 = gp%y(g1)
            x2 = gp%x(g2); y2 = gp%y(g2)
            x3 = gp%x(g3); y3 = gp%y(g3)
            a2 = (x2 - x1)*(y3 - y1) - (x3 - x1)*(y2 - y1)     ! 2A
            ! 2A dN_k/dx, 2A dN_k/dy
            b1x = y2 - y3; b2x = y3 - y1; b3x = y1 - y2
            b1y = x3 - x2; b2y = x1 - x3; b3y = x2 - x1
            work%bx(:, i) = [b1x, b2x, b3x]
            work%by(:, i) = [b1y, b2y, b3y]
            work%area2(i) = a2
            ! growth of the vertex stiffness terms (zones_stiffness)
            st = abs(b1x) + abs(b1y) + abs(b2x) + abs(b2y) + abs(b3x) + abs(b3y)
            grow = max(grow, (abs(b1x) + abs(b1y))*st - stiffer_limit*work%kref(1, i)*a2, &
                       (abs(b2x) + abs(b2y))*st - stiffer_limit*work%kref(2, i)*a2, &
                       (abs(b3x) + abs(b3y))*st - stiffer_limit*work%kref(3, i)*a2)
            r = dt/a2
            dvxdx = (gp%vx(g1)*b1x + gp%vx(g2)*b2x + gp%vx(g3)*b3x)*r
            dvxdy = (gp%vx(g1)*b1y + gp%vx(g2)*b2y + gp%vx(g3)*b3y)*r
            dvydx = (gp%vy(g1)*b1x + gp%vy(g2)*b2x + gp%vy(g3)*b3x)*r
            dvydy = (gp%vy(g1)*b1y + gp%vy(g2)*b2y + gp%vy(g3)*b3y)*r
            work%dxx(i) = dvxdx
            work%dyy(i) = dvydy
            work%dxy(i) = 0.5_wp*(dvxdy + dvydx)
            work%pev(i) = dvxdx + dvydy
            ! rotation of the old stresses (Jaumann)
            dth = 0.5_wp*(dvydx - dvxdy)
            sxx = zn%sxx(z)
            syy = zn%syy(z)
            sxy = zn%sxy(z)
            zn%sxx(z) = sxx - 2.0_wp*sxy*dth
            zn%syy(z) = syy + 2.0_wp*sxy*dth
            zn%sxy(z) = sxy + (sxx - syy)*dth
         end do
         if (grow > 0.0_wp) work%stiffer = .true.
         ! volumetric increments of mixed zones: mean of the pair (work%pev
         ! keeps each zone's own value, so a one-way partner's pair is unchanged)
         if (work%any_mixed) then
            call group_sums(work, ntot)
            do i = 1, ntot
               j = work%mgroup(i)
               if (j == 0) cycle
               evn = work%msum(j)/work%marea(j)
               ev = 0.5_wp*(evn - work%pev(i))
               work%dxx(i) = work%dxx(i) + ev
               work%dyy(i) = work%dyy(i) + ev
            end do
            ! in-plane mean stress before the model call (for the stress pairing below)
            do i = 1, ntot
               z = work%gidx(i)
               work%pold(i) = 0.5_wp*(zn%sxx(z) + zn%syy(z))
            end do
         end if
         do g = 1, work%ngroup
            i0 = work%gstart(g)
            n = work%gstart(g + 1) - i0
            call work%models(work%gcons(g))%model%update(work%gprops(g), work%gidx(i0:i0 + n - 1), n, &
                                                         work%dxx(i0:i0 + n - 1), work%dyy(i0:i0 + n - 1), &
                                                         work%dxy(i0:i0 + n - 1), zn)
         end do
         ! The same pairing on the stress (as FLAC3D's mixed discretization
         ! runs "similar loops based on stress, after calling the constitutive
         ! model"): the in-plane mean stress increment of each mixed zone is
         ! replaced by the area-weighted mean over the pair. Without it the two
         ! zones of a pair can drift apart in pressure under dilatant flow (a
         ! dilatant Mohr-Coulomb sample zoned by GENERATE EDGE lost a third of
         ! its strength after the peak with a nodal average lacking this step,
         ! tests/scripts/probe_zone_decks.py deck 12).
         ! The shift may leave a zone at yield outside its surface (its
         ! partner took more tension); left there, the next step's return
         ! and pairing feed each other and the pair's stresses run away (a
         ! compression test carried many times its strength, issue 18). So
         ! the zones pushed out are returned again, which changes their mean
         ! stress once more: pairing and return alternate until no zone
         ! needs returning (or pair_passes times), and a return ends it, so
         ! every zone leaves the step on or inside its surface.
         if (work%any_mixed) then
            do pass = 1, pair_passes
               do i = 1, ntot
                  z = work%gidx(i)
                  work%pev(i) = 0.5_wp*(zn%sxx(z) + zn%syy(z)) - work%pold(i)
               end do
               call group_sums(work, ntot)
               do i = 1, ntot
                  j = work%mgroup(i)
                  if (j == 0) cycle
                  z = work%gidx(i)
                  ev = work%msum(j)/work%marea(j) - work%pev(i)
                  zn%sxx(z) = zn%sxx(z) + ev
                  zn%syy(z) = zn%syy(z) + ev
               end do
               nback = 0
               do g = 1, work%ngroup
                  i0 = work%gstart(g)
                  n = work%gstart(g + 1) - i0
                  call work%models(work%gcons(g))%model%admissible(work%gprops(g), &
                                                                   work%gidx(i0:i0 + n - 1), n, zn, nback)
               end do
               if (nback == 0) exit
            end do
         end if
         do i = 1, ntot
            z = work%gidx(i)
            sxx = 0.5_wp*zn%sxx(z)
            syy = 0.5_wp*zn%syy(z)
            sxy = 0.5_wp*zn%sxy(z)
            g1 = zn%g1(z); g2 = zn%g2(z); g3 = zn%g3(z)
            gp%fx(g1) = gp%fx(g1) - (sxx*work%bx(1, i) + sxy*work%by(1, i))
            gp%fy(g1) = gp%fy(g1) - (sxy*work%bx(1, i) + syy*work%by(1, i))
            gp%fx(g2) = gp%fx(g2) - (sxx*work%bx(2, i) + sxy*work%by(2, i))
            gp%fy(g2) = gp%fy(g2) - (sxy*work%bx(2, i) + syy*work%by(2, i))
            gp%fx(g3) = gp%fx(g3) - (sxx*work%bx(3, i) + sxy*work%by(3, i))
            gp%fy(g3) = gp%fy(g3) - (sxy*work%bx(3, i) + syy*work%by(3, i))
         end do
      end associate
   end subroutine zones_stress_pass

   !> Area-weighted sums of work%pev over each mixed group (mixed_groups),
   !> in msum / marea at the group's index. For a pair the sums are
   !> (0 + a) + b = a + b, the pair's own expression to the last bit.
   subroutine group_sums(work, ntot)
      type(zone_work_t), intent(inout) :: work
      integer(ip), intent(in) :: ntot
      integer(ip) :: i, j
      do i = 1, ntot
         j = work%mgroup(i)
         if (j == 0) cycle
         work%msum(j) = 0.0_wp
         work%marea(j) = 0.0_wp
      end do
      do i = 1, ntot
         j = work%mgroup(i)
         if (j == 0) cycle
         work%msum(j) = work%msum(j) + work%pev(i)*work%area2(i)
         work%marea(j) = work%marea(j) + work%area2(i)
      end do
   end subroutine group_sums

   !> Chunks of the threaded elastic pass (elastic_stress_pass): each group's
   !> zones (gidx order) are cut into nthreads chunks, chunk t of a group
   !> being zones chunk_first(i1, i2, t, n) .. chunk_first(i1, i2, t + 1, n) - 1.
   !> A gridpoint whose zones all lie in one chunk (of all groups) takes its
   !> terms directly from that chunk's thread, in zone order as one thread does;
   !> the terms of a gridpoint whose zones lie in more than one chunk (shared:
   !> the few along the chunks' borders) go to slots of zs, numbered in zone
   !> and vertex order, and gather_forces subtracts them in the one-thread
   !> order. So each gridpoint's sum adds the same terms in the same order as
   !> one thread does, at any thread count.
   subroutine gather_lists(geo, work)
      type(geometry_t), intent(in) :: geo
      type(zone_work_t), intent(inout) :: work
      integer(ip) :: i, z, k, v, gv, c, t, g, nchunk, nslot, ns, run0, i1, i2
      logical :: border
      integer(ip), allocatable :: owner(:), fill(:), cnt(:)
      if (allocated(work%gshared)) deallocate (work%gshared, work%cslot, work%crun, work%zs, work%sgp, work%sptr, work%slist)
      if (allocated(work%gterm)) deallocate (work%gterm)
      work%nshared = 0
      if (work%nthreads <= 1) return
      associate (gp => geo%gridpoints, zn => geo%zones)
         allocate (work%gterm(5, max(1_ip, gp%n)))
         if (.not. work%elastic_only) return       ! the general zone pass runs on one thread
         nchunk = work%ngroup*work%nthreads
         allocate (owner(gp%n), work%gshared(max(1_ip, gp%n)), work%cslot(nchunk + 1), work%crun(2, nchunk))
         owner = 0
         work%gshared = .false.
         do g = 1, work%ngroup
            do t = 1, work%nthreads
               c = (g - 1)*work%nthreads + t
               do i = chunk_first(work%gstart(g), work%gstart(g + 1) - 1, t, work%nthreads), &
                      chunk_first(work%gstart(g), work%gstart(g + 1) - 1, t + 1, work%nthreads) - 1
                  z = work%gidx(i)
                  do v = 1, 3
                     gv = vertex(z, v)
                     if (owner(gv) == 0) then
                        owner(gv) = c
                     else if (owner(gv) /= c) then
                        work%gshared(gv) = .true.
                     end if
                  end do
               end do
            end do
         end do
         ! slots: the shared vertices in zone and vertex order, chunk by chunk
         nslot = 0
         allocate (cnt(gp%n))
         cnt = 0
         do g = 1, work%ngroup
            do t = 1, work%nthreads
               c = (g - 1)*work%nthreads + t
               work%cslot(c) = nslot + 1
               run0 = 0
               i1 = chunk_first(work%gstart(g), work%gstart(g + 1) - 1, t, work%nthreads)
               i2 = chunk_first(work%gstart(g), work%gstart(g + 1) - 1, t + 1, work%nthreads) - 1
               work%crun(:, c) = [i1, i1 - 1]        ! empty
               do i = i1, i2
                  z = work%gidx(i)
                  border = .false.
                  do v = 1, 3
                     gv = vertex(z, v)
                     if (.not. work%gshared(gv)) cycle
                     border = .true.
                     nslot = nslot + 1
                     cnt(gv) = cnt(gv) + 1
                  end do
                  ! the longest run of zones without a shared vertex
                  if (border) then
                     run0 = 0
                  else
                     if (run0 == 0) run0 = i
                     if (i - run0 > work%crun(2, c) - work%crun(1, c)) work%crun(:, c) = [run0, i]
                  end if
               end do
            end do
         end do
         work%cslot(nchunk + 1) = nslot + 1
         ns = count(work%gshared(1:gp%n))
         work%nshared = ns
         allocate (work%zs(2, max(1_ip, nslot)), work%sgp(max(1_ip, ns)), work%sptr(ns + 1), &
                   work%slist(max(1_ip, nslot)), fill(gp%n))
         work%sptr(1) = 1
         ns = 0
         do k = 1, gp%n
            if (.not. work%gshared(k)) cycle
            ns = ns + 1
            work%sgp(ns) = k
            fill(k) = work%sptr(ns)
            work%sptr(ns + 1) = work%sptr(ns) + cnt(k)
         end do
         nslot = 0
         do i = 1, work%gstart(work%ngroup + 1) - 1
            z = work%gidx(i)
            do v = 1, 3
               gv = vertex(z, v)
               if (.not. work%gshared(gv)) cycle
               nslot = nslot + 1
               work%slist(fill(gv)) = nslot
               fill(gv) = fill(gv) + 1
            end do
         end do
      end associate
   contains
      integer(ip) function vertex(z, v)
         integer(ip), intent(in) :: z, v
         select case (v)
         case (1); vertex = geo%zones%g1(z)
         case (2); vertex = geo%zones%g2(z)
         case default; vertex = geo%zones%g3(z)
         end select
      end function vertex
   end subroutine gather_lists

   !> First zone (gidx order) of chunk t of n of the zones i1..i2
   !> (gather_lists); chunk n + 1 starts at i2 + 1.
   pure integer(ip) function chunk_first(i1, i2, t, n) result(i)
      integer(ip), intent(in) :: i1, i2, t
      integer, intent(in) :: n
      i = i1 + ((t - 1)*(i2 - i1 + 1))/n
   end function chunk_first

   !> zones_stress_pass when every zone is elastic and none is mixed: strain
   !> rates, Jaumann rotation, Eq. 3 (the expressions of elastic_zone) and
   !> the nodal forces in one loop over the zones, with no work arrays
   !> between them. The order of the zones and every expression are those of
   !> zones_stress_pass, so the results are the same to the last bit. With
   !> more than one thread, the zones of a group are cut into one chunk a
   !> thread (gather_lists); a chunk's thread adds the terms of the gridpoints
   !> it alone touches and puts those of the shared ones in work%zs, which
   !> gather_forces then adds in the one-thread order: the same bits at any
   !> thread count.
   subroutine elastic_stress_pass(geo, work, dt)
      type(geometry_t), intent(inout) :: geo
      type(zone_work_t), intent(inout) :: work
      real(wp), intent(in) :: dt
      integer :: g
      real(wp) :: lam, mu2, grow, gr
      integer(ip) :: i1, i2, t, c, slot
      grow = -huge(1.0_wp)
      slot = 0
      associate (gp => geo%gridpoints, zn => geo%zones)
         do g = 1, work%ngroup
            call elastic_constants(work%gprops(g), lam, mu2)
            i1 = work%gstart(g)
            i2 = work%gstart(g + 1) - 1
            if (work%nthreads > 1 .and. allocated(work%gshared)) then
               !$omp parallel do schedule(static, 1) private(t, c, gr, slot) reduction(max:grow)
               do t = 1, work%nthreads
                  gr = -huge(1.0_wp)
                  c = (g - 1)*work%nthreads + t
                  slot = work%cslot(c) - 1
                  ! zones before the run, the run (the one-thread loop), zones after it
                  call elastic_zones(chunk_first(i1, i2, t, work%nthreads), work%crun(1, c) - 1, &
                                     work%gidx, zn%g1, zn%g2, zn%g3, gp%x, gp%y, gp%vx, gp%vy, gp%fx, gp%fy, &
                                     zn%sxx, zn%syy, zn%sxy, zn%szz, work%kref, lam, mu2, dt, gr, .true., &
                                     work%gshared, work%zs, slot)
                  call elastic_zones(work%crun(1, c), work%crun(2, c), &
                                     work%gidx, zn%g1, zn%g2, zn%g3, gp%x, gp%y, gp%vx, gp%vy, gp%fx, gp%fy, &
                                     zn%sxx, zn%syy, zn%sxy, zn%szz, work%kref, lam, mu2, dt, gr, .false., &
                                     work%gshared, work%zs, slot)
                  call elastic_zones(work%crun(2, c) + 1, chunk_first(i1, i2, t + 1, work%nthreads) - 1, &
                                     work%gidx, zn%g1, zn%g2, zn%g3, gp%x, gp%y, gp%vx, gp%vy, gp%fx, gp%fy, &
                                     zn%sxx, zn%syy, zn%sxy, zn%szz, work%kref, lam, mu2, dt, gr, .true., &
                                     work%gshared, work%zs, slot)
                  grow = max(grow, gr)
               end do
               !$omp end parallel do
            else
               call elastic_zones(i1, i2, work%gidx, zn%g1, zn%g2, zn%g3, &
                                  gp%x, gp%y, gp%vx, gp%vy, gp%fx, gp%fy, zn%sxx, zn%syy, zn%sxy, zn%szz, &
                                  work%kref, lam, mu2, dt, grow, .false., gp%live, work%kref, slot)
            end if
         end do
         if (work%nthreads > 1 .and. allocated(work%gshared)) &
            call gather_forces(work%nshared, work%sgp, work%sptr, work%slist, work%zs, gp%fx, gp%fy)
      end associate
      if (grow > 0.0_wp) work%stiffer = .true.
   end subroutine elastic_stress_pass

   !> The zones i1..i2 (gidx order) of one elastic group (elastic_stress_pass):
   !> arrays as explicit-shape dummies, so the loop reads them through plain
   !> base addresses. split: the force terms of a shared gridpoint (shared)
   !> go to zs(:, slot + 1), slot counting up, instead of fx, fy.
   subroutine elastic_zones(i1, i2, gidx, g1a, g2a, g3a, x, y, vx, vy, fx, fy, s11, s22, s12, s33, &
                            kref, lam, mu2, dt, grow, split, shared, zs, slot)
      integer(ip), intent(in) :: i1, i2
      integer(ip), intent(in) :: gidx(*), g1a(*), g2a(*), g3a(*)
      real(wp), intent(in) :: x(*), y(*), vx(*), vy(*), kref(3, *)
      real(wp), intent(inout) :: fx(*), fy(*), s11(*), s22(*), s12(*), s33(*)
      real(wp), intent(in) :: lam, mu2, dt
      real(wp), intent(inout) :: grow
      logical, intent(in) :: split
      logical(l1), intent(in) :: shared(*)
      real(wp), intent(inout) :: zs(2, *)
      integer(ip), intent(inout) :: slot
      integer(ip) :: i, z, g1, g2, g3
      real(wp) :: x1, y1, x2, y2, x3, y3, a2, b1x, b2x, b3x, b1y, b2y, b3y
      real(wp) :: dvxdx, dvxdy, dvydx, dvydy, dth, sxx, syy, sxy, szz, r, st, dv
      real(wp) :: exx, eyy, exy, t1x, t1y, t2x, t2y, t3x, t3y
      do i = i1, i2
         z = gidx(i)
         g1 = g1a(z); g2 = g2a(z); g3 = g3a(z)
         x1 = x(g1); y1 = y(g1)
         x2 = x(g2); y2 = y(g2)
         x3 = x(g3); y3 = y(g3)
         a2 = (x2 - x1)*(y3 - y1) - (x3 - x1)*(y2 - y1)     ! 2A
         b1x = y2 - y3; b2x = y3 - y1; b3x = y1 - y2
         b1y = x3 - x2; b2y = x1 - x3; b3y = x2 - x1
         st = abs(b1x) + abs(b1y) + abs(b2x) + abs(b2y) + abs(b3x) + abs(b3y)
         grow = max(grow, (abs(b1x) + abs(b1y))*st - stiffer_limit*kref(1, i)*a2, &
                    (abs(b2x) + abs(b2y))*st - stiffer_limit*kref(2, i)*a2, &
                    (abs(b3x) + abs(b3y))*st - stiffer_limit*kref(3, i)*a2)
         r = dt/a2
         dvxdx = (vx(g1)*b1x + vx(g2)*b2x + vx(g3)*b3x)*r
         dvxdy = (vx(g1)*b1y + vx(g2)*b2y + vx(g3)*b3y)*r
         dvydx = (vy(g1)*b1x + vy(g2)*b2x + vy(g3)*b3x)*r
         dvydy = (vy(g1)*b1y + vy(g2)*b2y + vy(g3)*b3y)*r
         exx = dvxdx
         eyy = dvydy
         exy = 0.5_wp*(dvxdy + dvydx)
         dth = 0.5_wp*(dvydx - dvxdy)
         sxx = s11(z)
         syy = s22(z)
         sxy = s12(z)
         szz = s33(z)
         x1 = sxx - 2.0_wp*sxy*dth
         y1 = syy + 2.0_wp*sxy*dth
         sxy = sxy + (sxx - syy)*dth
         sxx = x1
         syy = y1
         ! Eq. 3 (elastic_zone)
         dv = exx + eyy
         sxx = sxx + lam*dv + mu2*exx
         syy = syy + lam*dv + mu2*eyy
         sxy = sxy + mu2*exy
         szz = szz + lam*dv
         s11(z) = sxx
         s22(z) = syy
         s12(z) = sxy
         s33(z) = szz
         sxx = 0.5_wp*sxx
         syy = 0.5_wp*syy
         sxy = 0.5_wp*sxy
         if (split) then
            t1x = sxx*b1x + sxy*b1y
            t1y = sxy*b1x + syy*b1y
            t2x = sxx*b2x + sxy*b2y
            t2y = sxy*b2x + syy*b2y
            t3x = sxx*b3x + sxy*b3y
            t3y = sxy*b3x + syy*b3y
            if (shared(g1)) then
               slot = slot + 1
               zs(1, slot) = t1x
               zs(2, slot) = t1y
            else
               fx(g1) = fx(g1) - t1x
               fy(g1) = fy(g1) - t1y
            end if
            if (shared(g2)) then
               slot = slot + 1
               zs(1, slot) = t2x
               zs(2, slot) = t2y
            else
               fx(g2) = fx(g2) - t2x
               fy(g2) = fy(g2) - t2y
            end if
            if (shared(g3)) then
               slot = slot + 1
               zs(1, slot) = t3x
               zs(2, slot) = t3y
            else
               fx(g3) = fx(g3) - t3x
               fy(g3) = fy(g3) - t3y
            end if
         else
            fx(g1) = fx(g1) - (sxx*b1x + sxy*b1y)
            fy(g1) = fy(g1) - (sxy*b1x + syy*b1y)
            fx(g2) = fx(g2) - (sxx*b2x + sxy*b2y)
            fy(g2) = fy(g2) - (sxy*b2x + syy*b2y)
            fx(g3) = fx(g3) - (sxx*b3x + sxy*b3y)
            fy(g3) = fy(g3) - (sxy*b3x + syy*b3y)
         end if
      end do
   end subroutine elastic_zones

   !> Second pass of the threaded zone forces: each shared gridpoint sgp(j)
   !> subtracts its terms zs(:, slist(sptr(j):sptr(j+1)-1)) in the one-thread
   !> order (gather_lists). The shared gridpoints are the few along the
   !> chunks' borders: one thread.
   subroutine gather_forces(ns, sgp, sptr, slist, zs, fx, fy)
      integer(ip), intent(in) :: ns
      integer(ip), intent(in) :: sgp(*), sptr(*), slist(*)
      real(wp), intent(in) :: zs(2, *)
      real(wp), intent(inout) :: fx(*), fy(*)
      integer(ip) :: j, k, m, t
      real(wp) :: sx, sy
      do j = 1, ns
         k = sgp(j)
         sx = fx(k)
         sy = fy(k)
         do m = sptr(j), sptr(j + 1) - 1
            t = slist(m)
            sx = sx - zs(1, t)
            sy = sy - zs(2, t)
         end do
         fx(k) = sx
         fy(k) = sy
      end do
   end subroutine gather_forces

   !> One central-difference step of every free gridpoint: force sums of the
   !> last step plus gravity on the real mass, inertial mass work%m_in,
   !> mass-proportional damping alpha, local damping aloc (DAMP LOCAL: -aloc
   !> |F| sign(v) in x and in y); prescribed velocities (vfix bits) are
   !> left as they are. Corners of FDEF blocks follow their gridpoints (the
   !> rounding circle is translated with the corner). Returns in `res` the
   !> largest unbalanced force of a free direction and its gridpoint, the
   !> kinetic energy change, damping energy and the largest travel (as
   !> rigid_motion).
   !> The state of every live gridpoint it changes is first copied into
   !> save(:, k) = x y vx vy ux uy fx fy, so that a failed step can be undone
   !> (engine_rigid's motion_restore). With more than one thread the
   !> gridpoints are shared among the threads, each keeps its terms of the
   !> unbalanced force and the energies in work%gterm, and one pass in
   !> gridpoint order then takes the maximum and the sums as one thread does.
   subroutine gridpoint_motion(geo, work, ms, res, save)
      type(geometry_t), intent(inout) :: geo
      type(zone_work_t), intent(inout) :: work
      type(motion_step_t), intent(in) :: ms
      type(motion_result_t), intent(out) :: res
      real(wp), contiguous, intent(inout) :: save(:, :)
      integer(ip) :: k, t, nchunk, ku
      real(wp) :: f, tr, u, e1, e2, p1, p2, travel
      if (.not. work%active) return
      associate (gp => geo%gridpoints, co => geo%corners)
         if (gp%n == 0) return
         if (work%nthreads > 1) then
            nchunk = 4*work%nthreads
            travel = 0.0_wp
            !$omp parallel do schedule(static) private(t, tr, u, ku, e1, e2, p1, p2) reduction(max:travel)
            do t = 1, nchunk
               tr = 0.0_wp
               call gridpoint_steps(1 + (t - 1)*gp%n/nchunk, t*gp%n/nchunk, gp%live, work%still, gp%vfix, &
                                    gp%corner, work%m_in, gp%mass, gp%x, gp%y, gp%vx, gp%vy, gp%ux, gp%uy, &
                                    gp%fx, gp%fy, co%x, co%y, co%ux, co%uy, co%rx, co%ry, save, &
                                    ms, u, ku, e1, e2, p1, p2, tr, .true., work%gterm)
               travel = max(travel, tr)
            end do
            !$omp end parallel do
            res%travel = travel
            do k = 1, gp%n
               f = work%gterm(1, k)
               if (f < 0.0_wp) cycle           ! dead or still: no terms
               if (.not. (f <= res%unbal)) then      ! also catches NaN
                  res%unbal = f
                  res%at = k
               end if
               res%dke = res%dke + work%gterm(2, k)
               res%edamp = res%edamp + work%gterm(3, k)
               if (ms%probe) then
                  res%kvv = res%kvv + work%gterm(4, k)
                  res%mvv = res%mvv + work%gterm(5, k)
               end if
            end do
         else
            call gridpoint_steps(1_ip, gp%n, gp%live, work%still, gp%vfix, gp%corner, work%m_in, gp%mass, &
                                 gp%x, gp%y, gp%vx, gp%vy, gp%ux, gp%uy, gp%fx, gp%fy, &
                                 co%x, co%y, co%ux, co%uy, co%rx, co%ry, save, ms, &
                                 res%unbal, res%at, res%dke, res%edamp, res%kvv, res%mvv, res%travel, &
                                 .false., save)
         end if
      end associate
   end subroutine gridpoint_motion

   !> The loop of gridpoint_motion over gridpoints k1..k2, arrays as
   !> explicit-shape dummies. split: the unbalanced force and energy terms go to gterm(:, k) (-1 in gterm(1, k)
   !> for a gridpoint without terms) instead of unbal, ubgp, dke, edamp (and kvv, mvv).
   !> With ms%probe also the Rayleigh quotient's terms of the motion (core_motion's
   !> motion_result_t): save(7:8, k) still holds the force sums the last step
   !> started from, fxa, fya those it ended with, and v the velocity that moved
   !> the gridpoint between them, so -dF . v = dt v.K v on the free directions.
   subroutine gridpoint_steps(k1, k2, live, still, vfix, corner, m_in, mass, x, y, vx, vy, ux, uy, fxa, fya, &
                              cx, cy, cux, cuy, crx, cry, save, ms, &
                              unbal, ubgp, dke, edamp, kvv, mvv, travel, split, gterm)
      integer(ip), intent(in) :: k1, k2
      logical(l1), intent(in) :: live(*)
      logical, intent(in) :: still(*)
      integer, intent(in) :: vfix(*)
      integer(ip), intent(in) :: corner(*)
      real(wp), intent(in) :: m_in(*), mass(*), fxa(*), fya(*)
      real(wp), intent(inout) :: x(*), y(*), vx(*), vy(*), ux(*), uy(*)
      real(wp), intent(inout) :: cx(*), cy(*), cux(*), cuy(*), crx(*), cry(*)
      real(wp), intent(inout) :: save(8, *)
      type(motion_step_t), intent(in) :: ms
      real(wp), intent(inout) :: unbal, dke, edamp, kvv, mvv, travel
      integer(ip), intent(inout) :: ubgp
      logical, intent(in) :: split
      real(wp), intent(inout) :: gterm(5, *)
      integer(ip) :: k, c
      real(wp) :: m, fx, fy, vx0, vy0, vxn, vyn, dx, dy, f, tk, td, dfx, dfy, pk, pm
      dfx = 0.0_wp
      dfy = 0.0_wp
      do k = k1, k2
         if (.not. live(k)) then
            if (split) gterm(1, k) = -1.0_wp
            cycle
         end if
         if (ms%probe) then
            dfx = fxa(k) - save(7, k)
            dfy = fya(k) - save(8, k)
         end if
         save(1, k) = x(k); save(2, k) = y(k)
         save(3, k) = vx(k); save(4, k) = vy(k)
         save(5, k) = ux(k); save(6, k) = uy(k)
         save(7, k) = fxa(k); save(8, k) = fya(k)
         if (still(k)) then
            vx(k) = 0.0_wp
            vy(k) = 0.0_wp
            if (split) gterm(1, k) = -1.0_wp
            cycle
         end if
         m = m_in(k)
         fx = fxa(k) + mass(k)*ms%grav(1)
         fy = fya(k) + mass(k)*ms%grav(2)
         vx0 = vx(k)
         vy0 = vy(k)
         vxn = vx0
         vyn = vy0
         ! Eq. 28 and DAMP LOCAL per direction (core_damping.inc); the unbalanced force f
         ! is the undamped one
         pk = 0.0_wp
         pm = 0.0_wp
         if (iand(vfix(k), vfix_x) == 0) then
            vxn = damped_velocity(vx0, fx, m, ms%dt, ms%aloc, ms%con1, ms%con2)
            if (ms%probe) then
               pk = -dfx*vx0
               pm = m*vx0*vx0
            end if
         else
            fx = 0.0_wp
         end if
         if (iand(vfix(k), vfix_y) == 0) then
            vyn = damped_velocity(vy0, fy, m, ms%dt, ms%aloc, ms%con1, ms%con2)
            if (ms%probe) then
               pk = pk - dfy*vy0
               pm = pm + m*vy0*vy0
            end if
         else
            fy = 0.0_wp
         end if
         f = sqrt(fx*fx + fy*fy)        ! not hypot: a libm call, a quarter of a plastic step
         tk = 0.5_wp*m*abs(vxn*vxn + vyn*vyn - vx0*vx0 - vy0*vy0)
         td = ms%alpha*ms%dt*0.25_wp*m*((vx0 + vxn)**2 + (vy0 + vyn)**2)
         if (split) then
            gterm(1, k) = f
            gterm(2, k) = tk
            gterm(3, k) = td
            gterm(4, k) = pk
            gterm(5, k) = pm
         else
            kvv = kvv + pk
            mvv = mvv + pm
            if (.not. (f <= unbal)) then      ! also catches NaN
               unbal = f
               ubgp = k
            end if
            dke = dke + tk
            edamp = edamp + td
         end if
         vx(k) = vxn
         vy(k) = vyn
         dx = vxn*ms%dt
         dy = vyn*ms%dt
         x(k) = x(k) + dx
         y(k) = y(k) + dy
         ux(k) = ux(k) + dx
         uy(k) = uy(k) + dy
         travel = max(travel, abs(dx) + abs(dy))
         c = corner(k)
         if (c > 0) then
            cx(c) = x(k)
            cy(c) = y(k)
            cux(c) = cux(c) + dx
            cuy(c) = cuy(c) + dy
            crx(c) = crx(c) + dx
            cry(c) = cry(c) + dy
         end if
      end do
   end subroutine gridpoint_steps

   !> Centroids (and areas) of FDEF blocks from their current corners, so
   !> that range selections (CHANGE, PRINT, ...) see the deformed blocks.
   subroutine zones_block_centroids(geo)
      type(geometry_t), intent(inout) :: geo
      integer(ip) :: b, c, k
      real(wp) :: a, cx, cy, cr, x1, y1, x2, y2
      associate (bl => geo%blocks, co => geo%corners)
         do b = 1, bl%n
            if (.not. (bl%live(b) .and. bl%fdef(b))) cycle
            if (bl%nzone(b) == 0) cycle
            a = 0.0_wp
            cx = 0.0_wp
            cy = 0.0_wp
            c = bl%first_corner(b)
            do k = 1, bl%ncorner(b)
               x1 = co%x(c); y1 = co%y(c)
               x2 = co%x(co%next(c)); y2 = co%y(co%next(c))
               cr = x1*y2 - x2*y1
               a = a + cr
               cx = cx + (x1 + x2)*cr
               cy = cy + (y1 + y2)*cr
               c = co%next(c)
            end do
            if (a == 0.0_wp) cycle
            bl%xc(b) = cx/(3.0_wp*a)
            bl%yc(b) = cy/(3.0_wp*a)
            bl%area(b) = -0.5_wp*a
         end do
      end associate
   end subroutine zones_block_centroids

end module zones_mechanics
