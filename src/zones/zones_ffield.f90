!> The dynamic free field (manual Section 3.8.2, Eqs. 31-36): a 1-D column
!> (model_ffield) stepped in parallel with the blocks, and its coupling to
!> the lateral boundary points flagged by BOUNDARY FF.
!>
!> Column (Section 3.8.2.2). Gridpoint masses rho dy / 2 from each zone next
!> to it (unit width). Each step, as the blocks' gridpoints (Section 3.4):
!>    v := (v (1 - alpha dt / 2) + F / m dt) / (1 + alpha dt / 2),  u := u + v dt
!> with F the force sum of the last step plus gravity m g (less the water's
!> weight below SET YWTAB under effective stresses, as the zones' buoyancy
!> in fluid_flow), alpha the mass-
!> proportional damping constant of the model (DAMP). Then the zone strain
!> increments (Eq. 32; tensor components, as the zones' kernels take them)
!>    d eps_yy = (vy(i+1) - vy(i)) / dy dt,   d eps_xy = (vx(i+1) - vx(i)) / (2 dy) dt,
!>    d eps_xx = 0,
!> the zones' constitutive models (CONS 0, 1, 3 of zones_models) give the
!> stresses, and the forces are (Eq. 33, stresses tension positive)
!>    F_x(i) = sxy(i) - sxy(i-1),   F_y(i) = syy(i) - syy(i-1)
!> (zone 0 and zone np are absent: the top is a free surface). The base
!> (gridpoint 1) takes the FFIELD conditions: a prescribed velocity; or the
!> stress s h(t) as the traction -s on the outward normal -y (SXY in x,
!> SXX the normal stress in y, h the BOUNDARY history captured with it); a
!> dashpot -rho c v (c_s in x, c_p in y, the base zone's material) when
!> viscous; and the support's reaction stored when a viscous condition
!> replaced a velocity (model_ffield).
!>
!> Coupling (Section 3.8.2.3). For a point of the lateral boundary with
!> outward normal n_x = -1 (left, AB) or +1 (right, CD), on each of its
!> half edges to another BOUNDARY FF point the free-field stresses act as the
!> traction (Eq. 34)
!>    t_x = n_x (sxx - sxx0),   t_y = n_x (sxy - sxy0),
!> integrated exactly over the half edge's y-interval (the column's stresses
!> are uniform per zone; sxx0, sxy0 are the stresses saved by FFIELD
!> INITIALIZE). The manual applies the same integral as point forces at the
!> column's gridpoint heights (Eq. 35); both are the same resultant. The
!> dashpots of Eq. 36, -rho c (v - v_f) l, are the viscous boundary's
!> (zones_viscous) with the free-field velocity v_f, interpolated linearly
!> in the column at the point's height, subtracted: this module sets
!> `viscous_work_t%vfx / vfy` for the points it owns. A direction held by a
!> prescribed velocity takes no free-field force.
!>
!> Stable step of the column: dy / c_p of its stiffest zone (the 1-D
!> lumped-mass chain's critical step) times the zones' FRACTION, and m / c
!> for the base gridpoint's dashpots (as zones_viscous; under MSCALE PART
!> tdel its mass is raised to reach tdel instead); the engine takes the
!> smaller of it and its own step.
module zones_ffield
   use core_forces, only: add_rigid_force
   use core_kinds, only: wp, ip, i8, l1
   use core_motion, only: stage_args_t
   use core_error, only: error_t, set_error
   use model_geometry, only: geometry_t
   use model_materials, only: material_table_t
   use model_boundary, only: boundary_t, boundary_history_value, bc_velocity, bh_constant
   use model_ffield, only: ffield_t, ffield_zone_at, ff_stress, ff_velocity
   use zones_models, only: zone_props_t, zone_props_of, zone_model_t, zone_model_create, zone_groups
   use zones_boundary_setup, only: block_grid_t, block_grid_build, corner_free_sides
   use zones_viscous, only: viscous_work_t, boundary_point_live
   implicit none
   private
   public :: ffield_work_t, ffield_prepare, ffield_column_step, ffield_column_forces, &
             ffield_apply, ffield_cycle_end

   type :: holder_t
      class(zone_model_t), allocatable :: model
   end type holder_t

   type :: ffield_work_t
      logical :: active = .false.
      real(wp), allocatable :: m(:)                  !< (np) gridpoint masses
      real(wp), allocatable :: mg(:)                 !< (np) their weight / g (buoyant)
      ! zone groups sharing (cons, material), contiguous in gidx
      integer :: ngroup = 0
      integer, allocatable :: gcons(:), gstart(:)
      integer(ip), allocatable :: gidx(:)
      type(zone_props_t), allocatable :: gprops(:)
      type(holder_t), allocatable :: models(:)       !< per group
      real(wp), allocatable :: dxx(:), dyy(:), dxy(:)  !< (np - 1) scratch, gidx order
      real(wp) :: base_imp(2) = 0.0_wp               !< rho c_s, rho c_p of the base zone
      real(wp) :: dt_max = huge(1.0_wp)
      ! coupled points
      integer(ip) :: n = 0
      integer(ip), allocatable :: point(:)           !< index in the boundary list
      integer(ip), allocatable :: kvis(:)            !< index among the viscous points, 0 none
      real(wp), allocatable :: nx(:)                 !< outward normal x (-1 left, +1 right)
      integer, allocatable :: nedge(:)               !< half edges to other FF points (0..2)
      real(wp), allocatable :: ya(:, :), yb(:, :)    !< (2, n) their y-intervals
   end type ffield_work_t

contains

   !> Masses, zone groups, base impedances, stable step and the coupled
   !> points (BOUNDARY FF points of live corners). Fails naming the zone's
   !> material when it lacks density or moduli.
   subroutine ffield_prepare(fw, ff, bnd, geo, mats, vw, frac_zone, tdel, rhow, ywtab, error)
      type(ffield_work_t), intent(inout) :: fw
      type(ffield_t), intent(in) :: ff
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      type(material_table_t), intent(in) :: mats
      type(viscous_work_t), intent(in) :: vw
      real(wp), intent(in) :: frac_zone, tdel
      !> buoyancy (FLUID density and SET YWTAB, effective stresses; 0: none)
      real(wp), intent(in) :: rhow, ywtab
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: nz, z, i, k, c, n
      integer :: g, ng, mat
      integer, allocatable :: gmat(:), zgroup(:)
      real(wp) :: rho, kb, gs, cp, xmid, xmin, xmax
      type(block_grid_t) :: grid
      integer(ip), allocatable :: vis_of(:)
      logical :: fp, fn
      character(len=200) :: msg

      fw%active = .false.
      fw%n = 0
      fw%dt_max = huge(1.0_wp)
      if (.not. ff%on .or. ff%np < 2) return
      nz = ff%np - 1
      ! groups by (cons, material)
      call zone_groups(ff%cons(1:nz), ff%mat(1:nz), spread(.true._l1, 1, nz), zgroup, fw%gcons, gmat, &
                       fw%gstart, fw%gidx)
      ng = size(gmat)
      fw%ngroup = ng
      if (allocated(fw%gprops)) deallocate (fw%gprops, fw%models)
      allocate (fw%gprops(ng), fw%models(ng))
      do g = 1, ng
         call zone_model_create(fw%gcons(g), fw%models(g)%model, error)
         if (allocated(error)) then
            error%message = 'FFIELD '//error%message
            return
         end if
         mat = gmat(g)
         fw%gprops(g) = zone_props_of(mats, mat)
         if (fw%gprops(g)%density <= 0.0_wp .or. fw%gprops(g)%bulk <= 0.0_wp .or. &
             fw%gprops(g)%shear <= 0.0_wp) then
            write (msg, '(a,i0,a,i0,a)') 'CYCLE: the free-field zones of material ', mat, &
               ' need DENSITY, K and G: give PROPERTY MAT=', mat, &
               ' D=.. K=.. G=.. (or FFIELD MAT n for another material)'
            call set_error(error, trim(msg))
            return
         end if
      end do
      if (allocated(fw%dxx)) deallocate (fw%dxx, fw%dyy, fw%dxy, fw%m, fw%mg)
      allocate (fw%dxx(nz), fw%dyy(nz), fw%dxy(nz), fw%m(ff%np), fw%mg(ff%np))
      fw%m = 0.0_wp
      fw%mg = 0.0_wp
      do z = 1, nz
         g = zgroup(z)
         rho = fw%gprops(g)%density
         kb = fw%gprops(g)%bulk
         gs = fw%gprops(g)%shear
         fw%m(z) = fw%m(z) + 0.5_wp*rho*ff%dy
         fw%m(z + 1) = fw%m(z + 1) + 0.5_wp*rho*ff%dy
         ! the weight: less the water's below the water table (as the
         ! fluid stage's buoyancy of the zones, fluid_flow)
         if (ff%yl + (real(z, wp) - 0.5_wp)*ff%dy < ywtab) rho = rho - rhow
         fw%mg(z) = fw%mg(z) + 0.5_wp*rho*ff%dy
         fw%mg(z + 1) = fw%mg(z + 1) + 0.5_wp*rho*ff%dy
         cp = sqrt((kb + 4.0_wp*gs/3.0_wp)/rho)
         fw%dt_max = min(fw%dt_max, frac_zone*ff%dy/cp)
         if (z == 1) fw%base_imp = [sqrt(rho*gs), sqrt(rho*(kb + 4.0_wp*gs/3.0_wp))]
      end do
      ! the base dashpots: c dt / m <= 1 (zones_viscous); under MSCALE PART
      ! tdel the base mass is raised to reach tdel instead
      do k = 1, 2
         if (.not. ff%base_visc(k) .or. ff%base_code(k) == ff_velocity) cycle
         if (tdel > 0.0_wp) fw%m(1) = max(fw%m(1), fw%base_imp(k)*tdel)
         fw%dt_max = min(fw%dt_max, fw%m(1)/fw%base_imp(k))
      end do

      ! coupled points: BOUNDARY FF points of live corners; side from the
      ! middle of their x-extent
      n = 0
      if (allocated(bnd%ff)) then
         do i = 1, bnd%n
            if (bnd%ff(i) /= 0 .and. boundary_point_live(bnd, geo, i)) n = n + 1
         end do
      end if
      if (allocated(fw%point)) deallocate (fw%point, fw%kvis, fw%nx, fw%nedge, fw%ya, fw%yb)
      allocate (fw%point(n), fw%kvis(n), fw%nx(n), fw%nedge(n), fw%ya(2, n), fw%yb(2, n))
      fw%active = .true.
      if (n == 0) return
      allocate (vis_of(bnd%n))
      vis_of = 0
      do k = 1, vw%n
         vis_of(vw%point(k)) = k
      end do
      xmin = huge(1.0_wp)
      xmax = -huge(1.0_wp)
      k = 0
      do i = 1, bnd%n
         if (bnd%ff(i) == 0 .or. .not. boundary_point_live(bnd, geo, i)) cycle
         k = k + 1
         fw%point(k) = i
         fw%kvis(k) = vis_of(i)
         c = bnd%corner(i)
         xmin = min(xmin, geo%corners%x(c))
         xmax = max(xmax, geo%corners%x(c))
      end do
      xmid = 0.5_wp*(xmin + xmax)
      call block_grid_build(geo, grid)
      do k = 1, n
         c = bnd%corner(fw%point(k))
         fw%nx(k) = merge(-1.0_wp, 1.0_wp, geo%corners%x(c) < xmid)
         fw%nedge(k) = 0
         call corner_free_sides(geo, grid, c, fp, fn)
         if (fn) call add_edge(k, c, geo%corners%next(c))
         if (fp) call add_edge(k, c, geo%corners%prev(c))
      end do
      fw%n = n

   contains

      !> The half edge from corner a towards corner b, if b is an FF point.
      subroutine add_edge(kk, a, b)
         integer(ip), intent(in) :: kk, a, b
         integer(ip) :: j
         logical :: ffb
         ffb = .false.
         do j = 1, bnd%n
            if (bnd%corner(j) == b) then
               ffb = bnd%ff(j) /= 0
               exit
            end if
         end do
         if (.not. ffb) return
         ! lateral edges only (a base corner's bottom edge is the base's)
         if (abs(geo%corners%x(b) - geo%corners%x(a)) >= abs(geo%corners%y(b) - geo%corners%y(a))) &
            return
         fw%nedge(kk) = fw%nedge(kk) + 1
         fw%ya(fw%nedge(kk), kk) = geo%corners%y(a)
         fw%yb(fw%nedge(kk), kk) = 0.5_wp*(geo%corners%y(a) + geo%corners%y(b))
      end subroutine add_edge
   end subroutine ffield_prepare

   !> Force sums of the column from its stresses (Eq. 33) and the base
   !> conditions at problem time `time` (step k of ncycles).
   subroutine ffield_column_forces(ff, fw, bnd, time, k, ncycles)
      type(ffield_t), intent(inout) :: ff
      type(ffield_work_t), intent(in) :: fw
      type(boundary_t), intent(in) :: bnd
      real(wp), intent(in) :: time
      integer(i8), intent(in) :: k, ncycles
      integer(ip) :: i, np
      integer :: d
      real(wp) :: h, fb(2), v1(2)
      np = ff%np
      associate (zn => ff%zn)
         ff%fx(1) = zn%sxy(1)
         ff%fy(1) = zn%syy(1)
         do i = 2, np - 1
            ff%fx(i) = zn%sxy(i) - zn%sxy(i - 1)
            ff%fy(i) = zn%syy(i) - zn%syy(i - 1)
         end do
         ff%fx(np) = -zn%sxy(np - 1)
         ff%fy(np) = -zn%syy(np - 1)
      end associate
      ! base: stored reaction, stress times its history, dashpots
      h = 1.0_wp
      if (any(ff%base_code == ff_stress)) &
         h = boundary_history_value(bnd, ff%base_h, ff%base_freq, ff%base_tload, time, k, ncycles)
      v1 = [ff%vx(1), ff%vy(1)]
      do d = 1, 2
         fb(d) = ff%base_f(d)
         if (ff%base_code(d) == ff_stress) fb(d) = fb(d) - ff%base_s(d)*h
         if (ff%base_visc(d) .and. ff%base_code(d) /= ff_velocity) &
            fb(d) = fb(d) - fw%base_imp(d)*v1(d)
      end do
      ff%fx(1) = ff%fx(1) + fb(1)
      ff%fy(1) = ff%fy(1) + fb(2)
   end subroutine ffield_column_forces

   !> One step of the column (module header): motion from the forces of the
   !> last step, strains, stresses, new forces; `sa%bad` the first gridpoint
   !> whose velocity is not finite (0: none).
   subroutine ffield_column_step(ff, fw, bnd, sa)
      type(ffield_t), intent(inout) :: ff
      type(ffield_work_t), intent(inout) :: fw
      type(boundary_t), intent(in) :: bnd
      type(stage_args_t), intent(inout) :: sa
      real(wp) :: dt, rdy, h
      integer(ip) :: i, j, z, i0, n
      integer :: g
      dt = sa%ms%dt
      do i = 1, ff%np
         ff%vx(i) = (ff%vx(i)*sa%ms%con1 + (ff%fx(i) + fw%mg(i)*sa%ms%grav(1))/fw%m(i)*dt) &
                    *sa%ms%con2
         ff%vy(i) = (ff%vy(i)*sa%ms%con1 + (ff%fy(i) + fw%mg(i)*sa%ms%grav(2))/fw%m(i)*dt) &
                    *sa%ms%con2
      end do
      if (any(ff%base_code == ff_velocity)) then
         ! the base velocity times the BOUNDARY history captured with it
         ! (manual 4.5 FFIELD: "Histories defined in the BOUNDARY command
         ! are also used here"), as the model's own BOUNDARY XVEL / YVEL
         h = boundary_history_value(bnd, ff%base_h, ff%base_freq, ff%base_tload, sa%time, sa%k, &
                                    sa%ncycles)
         if (ff%base_code(1) == ff_velocity) ff%vx(1) = ff%base_v(1)*h
         if (ff%base_code(2) == ff_velocity) ff%vy(1) = ff%base_v(2)*h
      end if
      ff%ux = ff%ux + ff%vx*dt
      ff%uy = ff%uy + ff%vy*dt
      rdy = dt/ff%dy
      do g = 1, fw%ngroup
         i0 = fw%gstart(g)
         n = fw%gstart(g + 1) - i0
         do j = i0, i0 + n - 1
            z = fw%gidx(j)
            fw%dxx(j) = 0.0_wp
            fw%dyy(j) = (ff%vy(z + 1) - ff%vy(z))*rdy
            fw%dxy(j) = 0.5_wp*(ff%vx(z + 1) - ff%vx(z))*rdy
         end do
         call fw%models(g)%model%update(fw%gprops(g), fw%gidx(i0:i0 + n - 1), n, &
                                        fw%dxx(i0:i0 + n - 1), fw%dyy(i0:i0 + n - 1), &
                                        fw%dxy(i0:i0 + n - 1), ff%zn)
      end do
      call ffield_column_forces(ff, fw, bnd, sa%time, sa%k, sa%ncycles)
      ! the first gridpoint whose velocity is not finite (engine_cycle ends the CYCLE)
      sa%bad = 0
      do i = 1, ff%np
         if (.not. (abs(ff%vx(i)) + abs(ff%vy(i)) <= huge(1.0_wp))) then
            sa%bad = i
            exit
         end if
      end do
   end subroutine ffield_column_step

   !> End of a CYCLE of k of its ncycles steps at problem time `time`: a
   !> base velocity with a history keeps the value it had then, v h(t_end),
   !> from then on, as the model's BOUNDARY XVEL / YVEL do
   !> (boundary_cycle_end), so a SINE pulse is not given again by the next
   !> CYCLE. The history stays while a base stress still uses it.
   subroutine ffield_cycle_end(ff, bnd, time, k, ncycles)
      type(ffield_t), intent(inout) :: ff
      type(boundary_t), intent(in) :: bnd
      real(wp), intent(in) :: time
      integer(i8), intent(in) :: k, ncycles
      real(wp) :: h
      if (k <= 0 .or. .not. any(ff%base_code == ff_velocity)) return
      if (ff%base_h == bh_constant) return
      h = boundary_history_value(bnd, ff%base_h, ff%base_freq, ff%base_tload, time, k, ncycles)
      where (ff%base_code == ff_velocity) ff%base_v = ff%base_v*h
      if (.not. any(ff%base_code == ff_stress)) ff%base_h = bh_constant
   end subroutine ffield_cycle_end

   !> Coupling (module header): the free-field velocity at each coupled
   !> viscous point into `vw`, and the free-field traction into the force
   !> sums of the gridpoints (FDEF corners) or blocks (rigid corners).
   subroutine ffield_apply(ff, fw, bnd, geo, vw)
      type(ffield_t), intent(in) :: ff
      type(ffield_work_t), intent(in) :: fw
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(inout) :: geo
      type(viscous_work_t), intent(inout) :: vw
      integer(ip) :: k, i, c, b, g, kv, j
      integer :: e
      real(wp) :: u, w, ixx, ixy, fx, fy, sxx, sxy, rx, ry
      associate (co => geo%corners, bl => geo%blocks, gp => geo%gridpoints)
         do k = 1, fw%n
            i = fw%point(k)
            c = bnd%corner(i)
            kv = fw%kvis(k)
            if (kv > 0) then
               ! linear interpolation of the column's velocity at the point's height
               u = (co%y(c) - ff%yl)/ff%dy
               u = min(max(u, 0.0_wp), real(ff%np - 1, wp))
               j = min(int(u, ip), ff%np - 2_ip) + 1
               w = u - real(j - 1, wp)
               vw%vfx(kv) = (1.0_wp - w)*ff%vx(j) + w*ff%vx(j + 1)
               vw%vfy(kv) = (1.0_wp - w)*ff%vy(j) + w*ff%vy(j + 1)
            end if
            fx = 0.0_wp
            fy = 0.0_wp
            do e = 1, fw%nedge(k)
               call stress_integral(fw%ya(e, k), fw%yb(e, k), ixx, ixy)
               fx = fx + fw%nx(k)*ixx
               fy = fy + fw%nx(k)*ixy
            end do
            if (bnd%ix(i) == bc_velocity) fx = 0.0_wp
            if (bnd%iy(i) == bc_velocity) fy = 0.0_wp
            g = co%gp(c)
            if (g > 0) then
               gp%fx(g) = gp%fx(g) + fx
               gp%fy(g) = gp%fy(g) + fy
            else
               b = co%block(c)
               rx = co%x(c) - bl%xc(b)
               ry = co%y(c) - bl%yc(b)
               call add_rigid_force(bl%fx, bl%fy, bl%fm, b, rx, ry, fx, fy)
            end if
         end do
      end associate
   contains
      !> Integrals over y in [ya, yb] (either order) of sxx - sxx0 and
      !> sxy - sxy0 of the column (uniform per zone, the end zones beyond it).
      subroutine stress_integral(ya, yb, ixx, ixy)
         real(wp), intent(in) :: ya, yb
         real(wp), intent(out) :: ixx, ixy
         real(wp) :: lo, hi, za, zb, len
         integer(ip) :: z, z1, z2
         lo = min(ya, yb)
         hi = max(ya, yb)
         ixx = 0.0_wp
         ixy = 0.0_wp
         z1 = ffield_zone_at(ff, lo)
         z2 = ffield_zone_at(ff, hi)
         do z = z1, z2
            za = ff%yl + real(z - 1, wp)*ff%dy
            zb = za + ff%dy
            if (z == 1) za = -huge(1.0_wp)
            if (z == ff%np - 1) zb = huge(1.0_wp)
            len = min(hi, zb) - max(lo, za)
            if (len <= 0.0_wp) cycle
            sxx = ff%zn%sxx(z) - ff%sxx0(z)
            sxy = ff%zn%sxy(z) - ff%sxy0(z)
            ixx = ixx + sxx*len
            ixy = ixy + sxy*len
         end do
      end subroutine stress_integral

   end subroutine ffield_apply

end module zones_ffield
