!> Joint fluid flow and domain pressures (manual Section 3.12).
!>
!> Domains (geometry%domains, Fig 3-3e) hold a fluid pressure; fluid flows
!> between the two domains of every contact:
!>    edge contact (length l > 0):  q = kj a^3 (phi1 - phi2) / l   (Eq. 54)
!>    point contact (length 0):     q = kc (phi1 - phi2)             (Eq. 53)
!> kj = JPERM, kc = CPERM of the contact's joint material, hydraulic
!> aperture a = AZERO + un (un: joint normal displacement, opening
!> positive), limited to [ARES, CAPRATIO * max ARES] (Eq. 55 and the
!> PROPERTY caution). phi is the flow potential: the domain pressure p under
!> SET EFF (pressures exclude the hydrostatic part), p - rhow g.r under
!> SET -EFF (total pressures; r the domain position).
!>
!> A contact on the outer domain links its inner domain to a reservoir at
!> the contact point: pressure 0 unless BOUNDARY PP/PGRAD gave one, no flow
!> when BOUNDARY IMPERMEABLE. Under -EFF a domain at pressure <= 0 is dry:
!> it receives fluid but gives none, and its negative pressure stands for
!> the fluid missing to fill it (the pressure update is not clipped, so no
!> fluid is created); heads and forces use max(p, 0). This lets a free
!> surface form (verification F).
!>
!> Pressure update (Eq. 56), transient: p = p0 + Kw (Q dt / V - dV / V_m),
!> with V the fluid volume of the domain: its void area plus half of
!> a l of each contact of its ring (a joint's volume a l shared by its two
!> domains), at least vmin. The flow part is sub-stepped when dt exceeds the
!> stable step fw * V / (Kw sum k) (Eq. 57). SET SFLOW (steady state):
!> volumes play no role; each domain takes its own stable step, p = p +
!> fw Q / sum k (a Jacobi sweep), repeated within one mechanical step until
!> the pressure change since the step began exceeds PTOL (the manual's
!> trigger of the mechanical update) or the sweeps no longer change the
!> pressures, at most `max_sweeps` sweeps. PTOL is an absolute pressure
!> change in the deck's stress unit: Section 3.12 triggers the mechanics
!> "whenever the maximum increment of pressure in any domain exceeds some
!> prescribed tolerance", and verification F (an MPa deck, pressures up to
!> 0.04, the default 0.01) reaches its published steady state in its 1500
!> cycles only so (read as 1 % of the pressures it stops 24 % short). A
!> PTOL far below the model's pressures (a Pa deck with the default) makes
!> every sweep trigger the mechanics: CYCLE says so (engine_cycle).
!>
!> Forces: a domain's pressure acts on the block boundary between each pair
!> of consecutive contacts of its ring. For uniform p on any path from P0
!> to P1 along a clockwise block boundary, the force on the block is
!> p (dy, -dx) with (dx, dy) = P1 - P0, and its moment about the centroid
!> -p (|r1|^2 - |r0|^2) / 2: both depend on the end points only, so a block
!> surrounded by one pressure gets no net load. Fully-deformable blocks get
!> half of each arc's force at each end point, shared between the end
!> gridpoints of the edge there. SDEF blocks also take the arc's first
!> moments (qxx = fx mx, qyy = fy my, qxy = (fx my + fy mx) / 2 with (mx, my)
!> the mean point of the arc's chord from the centroid), which drive their
!> strain modes as the contact forces do. Under SET EFF with gravity, rigid blocks
!> whose centroid lies below the water table (SET YWTABLE) get the buoyancy
!> force -rhow g A; in fully-deformable blocks each zone below the water
!> table gives -rhow g A_z, a third to each of its gridpoints.
!>
!> Bingham fluid (FLUID COHW > 0, Section 3.13): an edge contact carries no
!> flow while the potential gradient |phi1 - phi2| / l stays below the
!> threshold J0 = 2 cohw / a (Eq. 63); above it
!> q = kj a^3 (|phi1 - phi2| - 2 cohw l / a) / l in the direction of the
!> gradient (the linear, shifted law of Fig. 3-24). Point contacts
!> (l = 0) have no length to carry a gradient and stay Newtonian.
module fluid_flow
   use core_forces, only: add_shared_force, add_sdef_moments
   use core_kinds, only: wp, ip
   use model_properties, only: prop_ares, prop_azero, prop_cperm, prop_jperm
   use model_geometry, only: geometry_t, contact_side, contact_side_fraction, contact_side_gridpoints
   use model_materials, only: material_table_t
   use model_fluid, only: fluid_t, fluid_size, bnd_open, bnd_pressure, bnd_impermeable
   implicit none
   private
   !> Most flow sub-steps one mechanical step may take (transient flow).
   real(wp), parameter, public :: max_substeps = 1.0e6_wp
   public :: fluid_work_t, fluid_sync, fluid_prepare
   public :: fluid_step, fluid_forces, fluid_mech_dt, fluid_joint_stiffness, fluid_flow_dt, fluid_positions
   public :: fluid_boundary_contact, fluid_aperture, fluid_pressure_scale, fluid_closed_count

   integer, parameter :: max_sweeps = 200

   !> Workspace of one CYCLE command.
   type :: fluid_work_t
      integer :: nmat = 0
      real(wp), allocatable :: kj(:), kc(:), azero(:), ares(:)   !< by joint material
      real(wp) :: amax = huge(1.0_wp)
      real(wp) :: vmin = 0.0_wp
      integer(ip), allocatable :: rside(:)            !< side of each ring entry
      real(wp), allocatable :: qsum(:), ksum(:), vnew(:), dp(:), kall(:)   !< by domain
      real(wp), allocatable :: cond(:)                !< conductance by contact
      integer :: nsub = 0            !< flow sub-steps of the last transient step
      !> the domain whose stable flow step was the smallest, when the step
      !> needed more than max_substeps of them (fluid_step then did nothing)
      integer(ip) :: too_stiff = 0
   end type fluid_work_t

contains

   !> Match the pressures to the current domains: after a domain rebuild
   !> (new or broken contacts, UPDOM) each new domain takes the mean pressure
   !> its contacts saw before (a fixed one wins, and stays fixed), so the
   !> pressure field survives renumbering. Domains must be valid.
   subroutine fluid_sync(fl, geo)
      type(fluid_t), intent(inout) :: fl
      type(geometry_t), intent(in) :: geo
      integer(ip) :: c, d, k, s, n, nc, nold, od
      real(wp) :: sum
      real(wp), allocatable :: oldp(:)
      logical, allocatable :: oldfix(:)
      logical :: fix, same
      nc = geo%contacts%n
      same = nc == fl%nc .and. geo%domains%n == fl%nd
      if (same) then
         do c = 1, nc
            if (.not. geo%contacts%live(c)) cycle
            if (fl%cdom1(c) /= inner(geo%contacts%dom1(c)) .or. &
                fl%cdom2(c) /= inner(geo%contacts%dom2(c))) then
               same = .false.
               exit
            end if
         end do
      end if
      if (same) return
      nold = fl%nd
      allocate (oldp(max(1, nold)), oldfix(max(1, nold)))
      oldp(1:nold) = fl%p(1:nold)
      oldfix(1:nold) = fl%fixed(1:nold)
      call fluid_size(fl, geo%domains%n, nc)
      do d = 1, geo%domains%n
         n = 0
         sum = 0.0_wp
         fix = .false.
         fl%p(d) = 0.0_wp
         fl%fixed(d) = .false.
         if (.not. geo%domains%live(d) .or. geo%domains%outer(d)) cycle
         do k = geo%domains%first(d), geo%domains%first(d) + geo%domains%count(d) - 1
            c = geo%domains%ring(k)
            do s = 1, 2
               if (merge(geo%contacts%dom1(c), geo%contacts%dom2(c), s == 1) /= d) cycle
               od = merge(fl%cdom1(c), fl%cdom2(c), s == 1)
               if (od < 1 .or. od > nold) cycle
               if (oldfix(od) .and. .not. fix) then
                  fix = .true.
                  n = 0
                  sum = 0.0_wp
               end if
               if (fix .and. .not. oldfix(od)) cycle
               n = n + 1
               sum = sum + oldp(od)
            end do
         end do
         if (n > 0) fl%p(d) = sum/real(n, wp)
         fl%fixed(d) = fix
      end do
      do c = 1, nc
         fl%cdom1(c) = -1
         fl%cdom2(c) = -1
         if (.not. geo%contacts%live(c)) cycle
         fl%cdom1(c) = inner(geo%contacts%dom1(c))
         fl%cdom2(c) = inner(geo%contacts%dom2(c))
      end do
   contains
      integer(ip) function inner(dd)
         integer(ip), intent(in) :: dd
         inner = 0
         if (dd < 1 .or. dd > geo%domains%n) return
         if (.not. geo%domains%outer(dd)) inner = dd
      end function inner
   end subroutine fluid_sync

   !> Is contact c on the outer domain (and which side is the inner one)?
   pure subroutine fluid_boundary_contact(geo, c, inner_side, on_boundary)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: c
      integer, intent(out) :: inner_side
      logical, intent(out) :: on_boundary
      logical :: o1, o2
      o1 = geo%domains%outer(geo%contacts%dom1(c))
      o2 = geo%domains%outer(geo%contacts%dom2(c))
      on_boundary = o1 .neqv. o2
      inner_side = merge(2, 1, o1)
   end subroutine fluid_boundary_contact

   !> Material tables, ring sides, positions and volumes (domains valid).
   subroutine fluid_prepare(fl, geo, mats, fw)
      type(fluid_t), intent(inout) :: fl
      type(geometry_t), intent(in) :: geo
      type(material_table_t), intent(in) :: mats
      type(fluid_work_t), intent(inout) :: fw
      integer :: j
      integer(ip) :: nd, nc, c, n
      real(wp) :: amaxres, lsum, amin
      call fluid_size(fl, geo%domains%n, geo%contacts%n)
      fw%nmat = max(1, mats%nmat)
      if (allocated(fw%kj)) deallocate (fw%kj, fw%kc, fw%azero, fw%ares)
      allocate (fw%kj(fw%nmat), fw%kc(fw%nmat), fw%azero(fw%nmat), fw%ares(fw%nmat))
      amaxres = 0.0_wp
      do j = 1, fw%nmat
         fw%kj(j) = mats%get(j, prop_jperm)
         fw%kc(j) = mats%get(j, prop_cperm)
         fw%azero(j) = mats%get(j, prop_azero)
         fw%ares(j) = mats%get(j, prop_ares)
         amaxres = max(amaxres, fw%ares(j))
      end do
      fw%amax = huge(1.0_wp)
      if (amaxres > 0.0_wp) fw%amax = fl%capratio*amaxres
      nd = geo%domains%n
      nc = geo%contacts%n
      if (allocated(fw%qsum)) deallocate (fw%qsum, fw%ksum, fw%vnew, fw%dp, fw%kall, fw%cond, &
                                          fw%rside)
      allocate (fw%qsum(max(1, nd)), fw%ksum(max(1, nd)), fw%vnew(max(1, nd)), fw%dp(max(1, nd)))
      allocate (fw%kall(max(1, nd)))
      allocate (fw%cond(max(1, nc)), fw%rside(max(1, geo%domains%nring)))
      call ring_sides(geo, fw%rside)
      ! smallest volume: a tenth of the smallest aperture over the mean contact length
      lsum = 0.0_wp
      n = 0
      do c = 1, nc
         if (.not. geo%contacts%live(c) .or. geo%contacts%length(c) <= 0.0_wp) cycle
         lsum = lsum + geo%contacts%length(c)
         n = n + 1
      end do
      amin = minval(fw%ares)
      if (amin <= 0.0_wp) amin = max(maxval(fw%azero), 1.0e-6_wp*geo%extent)
      if (n > 0) then
         fw%vmin = 0.1_wp*amin*lsum/real(n, wp)
      else
         fw%vmin = 0.1_wp*amin*geo%extent
      end if
      ! a domain of (next to) zero volume would divide by zero and ask for
      ! a million flow sub-steps a cycle (issue 20): at least 1e-12 of the
      ! model's area
      fw%vmin = max(fw%vmin, 1.0e-12_wp*geo%extent**2, tiny(1.0_wp))
      call fluid_positions(fl, geo)
      call apertures_and_volumes(fl, geo, fw)
      fl%vol(1:nd) = fw%vnew(1:nd)
   end subroutine fluid_prepare

   !> Domain positions: the mean of their ring's contact points.
   subroutine fluid_positions(fl, geo)
      type(fluid_t), intent(inout) :: fl
      type(geometry_t), intent(in) :: geo
      integer(ip) :: d, k, c
      real(wp) :: sx, sy
      call fluid_size(fl, geo%domains%n, geo%contacts%n)
      do d = 1, geo%domains%n
         sx = 0.0_wp
         sy = 0.0_wp
         do k = geo%domains%first(d), geo%domains%first(d) + geo%domains%count(d) - 1
            c = geo%domains%ring(k)
            sx = sx + geo%contacts%x(c)
            sy = sy + geo%contacts%y(c)
         end do
         if (geo%domains%count(d) > 0) then
            fl%xd(d) = sx/real(geo%domains%count(d), wp)
            fl%yd(d) = sy/real(geo%domains%count(d), wp)
         end if
      end do
   end subroutine fluid_positions

   !> Side (1: block1, 2: block2) of the contact at each ring entry: the
   !> arc ending there was walked along that block. A contact with both
   !> sides in one domain is resolved by the walk's rule: consecutive
   !> entries share a block (the block left at one contact is the block
   !> walked to the next).
   subroutine ring_sides(geo, rside)
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(out) :: rside(:)
      integer(ip) :: d, k0, k, j, n, f, c, cp, blk
      associate (dm => geo%domains, ct => geo%contacts)
         do d = 1, dm%n
            f = dm%first(d)
            n = dm%count(d)
            if (n == 0) cycle
            k0 = 0
            do k = f, f + n - 1
               c = dm%ring(k)
               if (ct%dom1(c) == d .neqv. ct%dom2(c) == d) then
                  k0 = k
                  exit
               end if
            end do
            if (k0 == 0) then
               k0 = f
               rside(k0) = 1
            else
               c = dm%ring(k0)
               rside(k0) = merge(1_ip, 2_ip, ct%dom1(c) == d)
            end if
            do j = 1, n - 1
               k = f + modulo(k0 - f + j, n)
               cp = dm%ring(f + modulo(k0 - f + j - 1, n))
               c = dm%ring(k)
               if (ct%dom1(c) == d .and. ct%dom2(c) == d) then
                  ! block left at the previous contact: the other side there
                  if (rside(f + modulo(k0 - f + j - 1, n)) == 1) then
                     blk = ct%block2(cp)
                  else
                     blk = ct%block1(cp)
                  end if
                  rside(k) = merge(1_ip, 2_ip, ct%block1(c) == blk)
               else
                  rside(k) = merge(1_ip, 2_ip, ct%dom1(c) == d)
               end if
            end do
         end do
      end associate
   end subroutine ring_sides

   !> Hydraulic aperture of contact c (Eq. 55, limited to [ARES, amax]).
   pure real(wp) function fluid_aperture(geo, fw, c) result(a)
      type(geometry_t), intent(in) :: geo
      type(fluid_work_t), intent(in) :: fw
      integer(ip), intent(in) :: c
      integer :: m
      m = min(max(int(geo%contacts%jmat(c)), 1), fw%nmat)
      a = fw%azero(m) + geo%contacts%state%un(c)
      a = min(max(a, fw%ares(m)), fw%amax)
      a = max(a, 0.0_wp)
   end function fluid_aperture

   !> Apertures and conductances of the contacts, fluid volumes of the domains.
   subroutine apertures_and_volumes(fl, geo, fw)
      type(fluid_t), intent(inout) :: fl
      type(geometry_t), intent(in) :: geo
      type(fluid_work_t), intent(inout) :: fw
      integer(ip) :: c, d, k
      integer :: m
      real(wp) :: a, l
      associate (ct => geo%contacts, dm => geo%domains)
         do c = 1, ct%n
            fw%cond(c) = 0.0_wp
            if (.not. ct%live(c)) cycle
            a = fluid_aperture(geo, fw, c)
            fl%aperture(c) = a
            m = min(max(int(ct%jmat(c)), 1), fw%nmat)
            l = ct%length(c)
            if (l > 0.0_wp) then
               fw%cond(c) = fw%kj(m)*a**3/l
            else
               fw%cond(c) = fw%kc(m)
            end if
         end do
         do d = 1, dm%n
            fw%vnew(d) = max(dm%area(d), 0.0_wp)
            do k = dm%first(d), dm%first(d) + dm%count(d) - 1
               c = dm%ring(k)
               fw%vnew(d) = fw%vnew(d) + 0.5_wp*fl%aperture(c)*ct%length(c)
            end do
            fw%vnew(d) = max(fw%vnew(d), fw%vmin)
         end do
      end associate
   end subroutine apertures_and_volumes

   !> Flow rates of all contacts from the current pressures; net inflow Q
   !> and conductance sum of every domain.
   subroutine flow_rates(fl, geo, fw, gravity)
      type(fluid_t), intent(inout) :: fl
      type(geometry_t), intent(in) :: geo
      type(fluid_work_t), intent(inout) :: fw
      real(wp), intent(in) :: gravity(2)
      integer(ip) :: c, d1, d2, nd
      real(wp) :: p1, p2, f1, f2, q, rg
      logical :: o1, o2, total
      total = .not. fl%eff
      rg = fl%rhow
      nd = geo%domains%n
      fw%qsum(1:nd) = 0.0_wp
      fw%ksum(1:nd) = 0.0_wp
      associate (ct => geo%contacts, dm => geo%domains)
         do c = 1, ct%n
            fl%q(c) = 0.0_wp
            if (.not. ct%live(c)) cycle
            if (fw%cond(c) <= 0.0_wp) cycle
            d1 = ct%dom1(c)
            d2 = ct%dom2(c)
            if (d1 == d2) cycle
            o1 = dm%outer(d1)
            o2 = dm%outer(d2)
            if (o1 .and. o2) cycle
            if (o1 .or. o2) then
               if (fl%bnd_code(c) == bnd_impermeable) cycle
            end if
            call end_head(o1, d1, p1, f1)
            call end_head(o2, d2, p2, f2)
            q = fw%cond(c)*(f1 - f2)
            ! Bingham fluid (COHW > 0, Section 3.13): no flow below the
            ! threshold gradient J0 = 2 cohw / a (Eq. 63); above it the flow
            ! grows linearly with the excess gradient (Fig. 3-24):
            ! q = kj a^3 (|J| - J0) sign(J), J = (phi1 - phi2) / l
            if (fl%cohw > 0.0_wp .and. ct%length(c) > 0.0_wp .and. fl%aperture(c) > 0.0_wp) &
               q = fw%cond(c)*sign(max(abs(f1 - f2) - 2.0_wp*fl%cohw*ct%length(c)/fl%aperture(c), &
                                       0.0_wp), f1 - f2)
            ! total pressures: a dry domain (p <= 0) gives no fluid
            if (total) then
               if (q > 0.0_wp .and. p1 <= 0.0_wp) q = 0.0_wp
               if (q < 0.0_wp .and. p2 <= 0.0_wp) q = 0.0_wp
            end if
            fl%q(c) = q
            if (.not. o1) then
               fw%qsum(d1) = fw%qsum(d1) - q
               fw%ksum(d1) = fw%ksum(d1) + fw%cond(c)
            end if
            if (.not. o2) then
               fw%qsum(d2) = fw%qsum(d2) + q
               fw%ksum(d2) = fw%ksum(d2) + fw%cond(c)
            end if
         end do
      end associate
   contains

      !> Pressure p and head f at one end of contact c: the boundary
      !> pressure of an outer domain (its PP, else 0), or domain d's pressure.
      subroutine end_head(outer, d, p, f)
         logical, intent(in) :: outer
         integer(ip), intent(in) :: d
         real(wp), intent(out) :: p, f
         if (outer) then
            p = 0.0_wp
            if (fl%bnd_code(c) == bnd_pressure) p = fl%bnd_p(c) + fl%bnd_g(c)*geo%contacts%y(c)
            f = p
            if (total) f = p - rg*(gravity(1)*geo%contacts%x(c) + gravity(2)*geo%contacts%y(c))
         else
            p = fl%p(d)
            f = p
            if (total) f = max(p, 0.0_wp) - rg*(gravity(1)*fl%xd(d) + gravity(2)*fl%yd(d))
         end if
      end subroutine end_head
   end subroutine flow_rates

   !> Stable fluid time step fw * min V / (Kw sum k) (Eq. 57) of the
   !> current apertures; huge when nothing flows.
   real(wp) function fluid_flow_dt(fl, geo, fw, frac, dmin) result(dt)
      type(fluid_t), intent(in) :: fl
      type(geometry_t), intent(in) :: geo
      type(fluid_work_t), intent(inout) :: fw
      real(wp), intent(in) :: frac
      integer(ip), intent(out), optional :: dmin   !< the domain that sets dt
      integer(ip) :: c, d, s
      real(wp) :: dt_d
      dt = huge(1.0_wp)
      if (present(dmin)) dmin = 0
      if (fl%bulkw <= 0.0_wp) return
      associate (ks => fw%kall)
      ks(1:geo%domains%n) = 0.0_wp
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         do s = 1, 2
            d = merge(geo%contacts%dom1(c), geo%contacts%dom2(c), s == 1)
            ks(d) = ks(d) + fw%cond(c)
         end do
      end do
      do d = 1, geo%domains%n
         if (.not. geo%domains%live(d) .or. geo%domains%outer(d) .or. fl%fixed(d)) cycle
         if (ks(d) > 0.0_wp) then
            dt_d = fw%vnew(d)/(fl%bulkw*ks(d))
            if (dt_d < dt) then
               dt = dt_d
               if (present(dmin)) dmin = d
            end if
         end if
      end do
      end associate
      if (dt < huge(1.0_wp)) dt = frac*dt
   end function fluid_flow_dt

   !> Bound on the mechanical step from the fluid's stiffness Kw / a on a
   !> joint (transient flow only; SFLOW ignores volume changes): a contact
   !> of length l adds Kw l / a to the normal stiffness, so with the
   !> smallest block mass m the step stays below 2 fb sqrt(m / k).
   real(wp) function fluid_mech_dt(fl, geo, fw, mmin, fb) result(dt)
      type(fluid_t), intent(in) :: fl
      type(geometry_t), intent(in) :: geo
      type(fluid_work_t), intent(in) :: fw
      real(wp), intent(in) :: mmin, fb
      real(wp) :: k, kunit
      dt = huge(1.0_wp)
      if (mmin <= 0.0_wp) return
      kunit = fluid_joint_stiffness(fl, geo, k)
      if (k > 0.0_wp) dt = 2.0_wp*fb*sqrt(mmin/k)
   end function fluid_mech_dt

   !> The fluid's normal stiffness on a joint per unit length, Kw / a
   !> [stress/length] (manual Section 3.12: "the fluid filling a joint
   !> increases the apparent stiffness by Kw/a"), the largest over the
   !> contacts; zero under SFLOW (volumes play no role) or without BULKW.
   !> Bounds the step of the gridpoints of fully-deformable blocks on a
   !> joint as JKN does (zones_timestep).
   !> `kforce`: the largest Kw l / a of a contact of length l [force/length].
   !> A contact between domains whose pressure cannot change (PFIXed, or the
   !> outer domain) adds nothing: its closing moves no pressure (all domains
   !> PFIXed, as the manual's `PFIX pressure=10` does, took a step 31 times
   !> smaller than the joints' for a fluid that never acted).
   real(wp) function fluid_joint_stiffness(fl, geo, kforce) result(k)
      type(fluid_t), intent(in) :: fl
      type(geometry_t), intent(in) :: geo
      real(wp), intent(out), optional :: kforce
      integer(ip) :: c
      real(wp) :: kf
      k = 0.0_wp
      kf = 0.0_wp
      if (fl%bulkw > 0.0_wp .and. .not. fl%sflow) then
         do c = 1, geo%contacts%n
            if (.not. geo%contacts%live(c)) cycle
            if (fl%aperture(c) <= 0.0_wp) cycle
            if (.not. (pressure_free(geo%contacts%dom1(c)) .or. pressure_free(geo%contacts%dom2(c)))) cycle
            k = max(k, fl%bulkw/fl%aperture(c))
            kf = max(kf, fl%bulkw*geo%contacts%length(c)/fl%aperture(c))
         end do
      end if
      if (present(kforce)) kforce = kf
   contains
      !> Domain d's pressure follows its volume (a live inner domain not PFIXed).
      logical function pressure_free(d)
         integer(ip), intent(in) :: d
         pressure_free = .false.
         if (d < 1 .or. d > geo%domains%n) return
         if (.not. geo%domains%live(d) .or. geo%domains%outer(d)) return
         if (d <= fl%nd) pressure_free = .not. fl%fixed(d)
         if (d > fl%nd) pressure_free = .true.
      end function pressure_free
   end function fluid_joint_stiffness

   !> The model's pressure scale: the largest magnitude of a domain pressure
   !> (PFIXed ones included) or of a boundary reservoir pressure (BOUNDARY PP /
   !> PGRAD at its contact); 0 before any pressure is known. CYCLE compares
   !> SET PTOL, an absolute pressure change, with it (engine_cycle).
   real(wp) function fluid_pressure_scale(fl, geo) result(scale)
      type(fluid_t), intent(in) :: fl
      type(geometry_t), intent(in) :: geo
      integer(ip) :: c, nd
      nd = min(geo%domains%n, fl%nd)
      scale = 0.0_wp
      if (nd > 0) scale = maxval(abs(fl%p(1:nd)))
      do c = 1, min(geo%contacts%n, fl%nc)
         if (fl%bnd_code(c) /= bnd_pressure) cycle
         if (.not. geo%contacts%live(c)) cycle
         scale = max(scale, abs(fl%bnd_p(c) + fl%bnd_g(c)*geo%contacts%y(c)))
      end do
   end function fluid_pressure_scale

   !> Live contacts that conduct no water in the last step (conductance 0:
   !> a joint closed to a hydraulic aperture of 0, Eq. 55 with ARES 0, or
   !> JPERM / CPERM 0) and all live contacts; CYCLE notes a model whose
   !> pressures drive no flow because no contact conducts (engine_cycle).
   subroutine fluid_closed_count(geo, fw, nclosed, nlive)
      type(geometry_t), intent(in) :: geo
      type(fluid_work_t), intent(in) :: fw
      integer(ip), intent(out) :: nclosed, nlive
      integer(ip) :: c
      nclosed = 0
      nlive = 0
      do c = 1, min(geo%contacts%n, int(size(fw%cond), ip))
         if (.not. geo%contacts%live(c)) cycle
         nlive = nlive + 1
         if (.not. fw%cond(c) > 0.0_wp) nclosed = nclosed + 1
      end do
   end subroutine fluid_closed_count

   !> One fluid step of length dt (module header); returns the largest
   !> pressure change.
   subroutine fluid_step(fl, geo, fw, gravity, dt, frac, dpmax)
      type(fluid_t), intent(inout) :: fl
      type(geometry_t), intent(in) :: geo
      type(fluid_work_t), intent(inout) :: fw
      real(wp), intent(in) :: gravity(2), dt, frac
      real(wp), intent(out) :: dpmax
      integer(ip) :: d, nd
      integer :: nsub, i
      real(wp) :: dtf, h, change, vm
      nd = geo%domains%n
      dpmax = 0.0_wp
      if (nd == 0) return
      call apertures_and_volumes(fl, geo, fw)
      if (fl%bulkw <= 0.0_wp) then
         fl%vol(1:nd) = fw%vnew(1:nd)
         return
      end if
      fw%dp(1:nd) = 0.0_wp
      if (fl%sflow) then
         do i = 1, max_sweeps
            call flow_rates(fl, geo, fw, gravity)
            change = 0.0_wp
            do d = 1, nd
               if (skip(d) .or. fw%ksum(d) <= 0.0_wp) cycle
               h = frac*fw%qsum(d)/fw%ksum(d)
               call apply(d, h)
               change = max(change, abs(h))
            end do
            dpmax = max(dpmax, maxval(abs(fw%dp(1:nd))))
            if (dpmax >= fl%ptol) exit
            if (change <= 1.0e-12_wp*max(maxval(abs(fl%p(1:nd))), tiny(1.0_wp))) exit
         end do
      else
         ! more sub-steps than max_substeps cannot be paid for (nor were they
         ! stable at the old cap): nothing is changed and the caller ends
         ! the CYCLE naming the domain
         dtf = fluid_flow_dt(fl, geo, fw, frac, fw%too_stiff)
         ! (divided: dtf is huge where no contact conducts, and huge times
         ! max_substeps overflowed, a floating-point trap in the Debug build)
         if (dtf < dt/max_substeps) return
         fw%too_stiff = 0
         ! volume change of the step (Eq. 56, second term)
         do d = 1, nd
            if (skip(d)) cycle
            vm = 0.5_wp*(fw%vnew(d) + fl%vol(d))
            if (vm > 0.0_wp) call apply(d, -fl%bulkw*(fw%vnew(d) - fl%vol(d))/vm)
         end do
         nsub = 1
         if (dtf < dt) nsub = ceiling(dt/dtf)
         h = dt/real(nsub, wp)
         fw%nsub = nsub
         do i = 1, nsub
            call flow_rates(fl, geo, fw, gravity)
            do d = 1, nd
               if (skip(d)) cycle
               call apply(d, fl%bulkw*fw%qsum(d)*h/fw%vnew(d))
            end do
         end do
         dpmax = maxval(abs(fw%dp(1:nd)))
      end if
      fl%vol(1:nd) = fw%vnew(1:nd)
   contains
      logical function skip(dd)
         integer(ip), intent(in) :: dd
         skip = .not. geo%domains%live(dd) .or. geo%domains%outer(dd) .or. fl%fixed(dd)
      end function skip
      subroutine apply(dd, inc)
         integer(ip), intent(in) :: dd
         real(wp), intent(in) :: inc
         real(wp) :: old
         old = fl%p(dd)
         fl%p(dd) = fl%p(dd) + inc
         fw%dp(dd) = fw%dp(dd) + (fl%p(dd) - old)
      end subroutine apply
   end subroutine fluid_step

   !> Domain pressures (and buoyancy under SET EFF) into the force sums of
   !> the blocks and gridpoints (module header).
   subroutine fluid_forces(fl, geo, fw, gravity)
      type(fluid_t), intent(in) :: fl
      type(geometry_t), intent(inout) :: geo
      type(fluid_work_t), intent(in) :: fw
      real(wp), intent(in) :: gravity(2)
      integer(ip) :: d, k, kp, f, n, c, cp, b, sp, s
      real(wp) :: p, x0, y0, x1, y1, fx, fy
      associate (dm => geo%domains, ct => geo%contacts, bl => geo%blocks)
         do d = 1, dm%n
            if (.not. dm%live(d) .or. dm%outer(d)) cycle
            p = fl%p(d)
            if (.not. fl%eff) p = max(p, 0.0_wp)
            if (p == 0.0_wp) cycle
            f = dm%first(d)
            n = dm%count(d)
            do k = f, f + n - 1
               kp = f + modulo(k - f - 1, n)
               c = dm%ring(k)
               cp = dm%ring(kp)
               s = fw%rside(k)
               sp = 3 - fw%rside(kp)
               b = merge(ct%block1(c), ct%block2(c), s == 1)
               call end_point(cp, sp, x0, y0)
               call end_point(c, s, x1, y1)
               fx = p*(y1 - y0)
               fy = -p*(x1 - x0)
               if (bl%fdef(b)) then
                  call to_gridpoints(cp, sp, 0.5_wp*fx, 0.5_wp*fy)
                  call to_gridpoints(c, s, 0.5_wp*fx, 0.5_wp*fy)
               else
                  bl%fx(b) = bl%fx(b) + fx
                  bl%fy(b) = bl%fy(b) + fy
                  bl%fm(b) = bl%fm(b) - 0.5_wp*p*((x1 - bl%xc(b))**2 + (y1 - bl%yc(b))**2 &
                                                  - (x0 - bl%xc(b))**2 - (y0 - bl%yc(b))**2)
                  ! an SDEF block's strain modes take the pressure's first
                  ! moments too (exact for a straight arc: its mean point),
                  ! as they take the contact forces': its corners move the
                  ! domain volumes, so without them the fluid's work on the
                  ! strain is never paid back and the coupling gains energy
                  if (bl%sdef(b)) call add_sdef_moments(bl%qxx, bl%qyy, bl%qxy, b, &
                                                        0.5_wp*(x0 + x1) - bl%xc(b), &
                                                        0.5_wp*(y0 + y1) - bl%yc(b), fx, fy)
               end if
            end do
         end do
         if (fl%eff .and. fl%rhow > 0.0_wp .and. any(gravity /= 0.0_wp)) then
            do b = 1, bl%n
               if (.not. bl%live(b) .or. bl%fdef(b)) cycle
               if (bl%yc(b) >= fl%ywtab) cycle
               bl%fx(b) = bl%fx(b) - fl%rhow*gravity(1)*bl%area(b)
               bl%fy(b) = bl%fy(b) - fl%rhow*gravity(2)*bl%area(b)
            end do
            call fdef_buoyancy()
         end if
      end associate
   contains
      !> Buoyancy of fully-deformable blocks: every zone of a live FDEF block
      !> whose centroid lies below the water table gives -rhow g A_z / 3 to
      !> each of its gridpoints (as gravity reaches them through the lumped
      !> masses), so a submerged block gets -rhow g A in all.
      subroutine fdef_buoyancy()
         integer(ip) :: z, g1, g2, g3
         real(wp) :: az, yz, bx, by
         associate (zn => geo%zones, gp => geo%gridpoints, bl => geo%blocks)
            do z = 1, zn%n
               if (.not. zn%live(z)) cycle
               if (.not. bl%live(zn%block(z))) cycle
               if (.not. bl%fdef(zn%block(z))) cycle
               g1 = zn%g1(z); g2 = zn%g2(z); g3 = zn%g3(z)
               yz = (gp%y(g1) + gp%y(g2) + gp%y(g3))/3.0_wp
               if (yz >= fl%ywtab) cycle
               az = 0.5_wp*abs((gp%x(g2) - gp%x(g1))*(gp%y(g3) - gp%y(g1)) &
                               - (gp%x(g3) - gp%x(g1))*(gp%y(g2) - gp%y(g1)))
               bx = -fl%rhow*gravity(1)*az/3.0_wp
               by = -fl%rhow*gravity(2)*az/3.0_wp
               gp%fx(g1) = gp%fx(g1) + bx; gp%fy(g1) = gp%fy(g1) + by
               gp%fx(g2) = gp%fx(g2) + bx; gp%fy(g2) = gp%fy(g2) + by
               gp%fx(g3) = gp%fx(g3) + bx; gp%fy(g3) = gp%fy(g3) + by
            end do
         end associate
      end subroutine fdef_buoyancy
      !> Where side s of contact cc lies on its block's boundary: the corner
      !> vertex, or the other block's corner vertex projected on the edge.
      subroutine end_point(cc, ss, x, y)
         integer(ip), intent(in) :: cc, ss
         real(wp), intent(out) :: x, y
         integer(ip) :: corner, edge, other, q
         real(wp) :: t
         call contact_side(geo, cc, ss, corner, edge, other)
         associate (co => geo%corners)
            if (corner > 0) then
               x = co%x(corner)
               y = co%y(corner)
               return
            end if
            q = co%next(edge)
            t = contact_side_fraction(geo, edge, other)
            x = co%x(edge) + t*(co%x(q) - co%x(edge))
            y = co%y(edge) + t*(co%y(q) - co%y(edge))
         end associate
      end subroutine end_point
      !> A point force at side s of contact cc of an FDEF block: to the
      !> corner's gridpoint, or shared by the edge's end gridpoints.
      subroutine to_gridpoints(cc, ss, gx, gy)
         integer(ip), intent(in) :: cc, ss
         real(wp), intent(in) :: gx, gy
         integer(ip) :: ga, gb
         real(wp) :: w
         call contact_side_gridpoints(geo, cc, ss, ga, gb, w)
         if (ga > 0 .and. gb > 0) &
            call add_shared_force(geo%gridpoints%fx, geo%gridpoints%fy, ga, gb, w, gx, gy)
      end subroutine to_gridpoints
   end subroutine fluid_forces

end module fluid_flow
