!> Non-reflecting (viscous) boundaries: BOUNDARY XVISC / YVISC with the
!> far-field material of BOUNDARY MAT n (manual Section 3.8.1.2, Eq. 30, after
!> Lysmer and Kuhlemeyer 1969). Independent dashpots on the boundary give the
!> tractions
!>
!>    tau_n = -rho c_p v_n,   tau_s = -rho c_s v_s
!>
!> with rho, c_p = sqrt((K + 4G/3)/rho), c_s = sqrt(G/rho) of the far-field
!> material and v_n, v_s the normal and shear components of the boundary
!> velocity. As in the manual they are applied like boundary loads, once per
!> step from the velocities of the step just taken (lagging half a step), so
!> they work for rigid and deformable blocks alike.
!>
!> Where a point's dashpots act: on the halves of the free edges next to it
!> whose other end is a viscous point too (a viscous segment, both ends in the
!> BOUNDARY range). So the corner of a model where a viscous base meets a
!> side that is not viscous takes the base half-edge only. The traction of
!> each half edge uses that edge's own outward normal; the force is the
!> traction times the half length. XVISC applies the x component of that
!> force, YVISC the y component (for the manual's straight x- and
!> y-boundaries that is the shear and the normal dashpot of Eq. 30). A
!> direction with a prescribed velocity takes no dashpot force.
!>
!> Stability: a dashpot c on a mass m, applied explicitly, damps in one step
!> as long as c dt / m <= 1. `viscous_prepare` returns that bound as
!> `dt_max` (the manual notes the possibility; a far-field material much
!> stiffer or denser than the model would otherwise make the step unstable),
!> and the engine takes the smaller of it and the usual time step. Under
!> MSCALE PART tdel the gridpoints too light for tdel are made heavier
!> instead (viscous_fit_masses), so that the step is tdel, as the manual's
!> Section 3.8.1.2 reports of the 1989 program ("no reduction of timestep
!> has been required by the use of the non-reflecting boundaries").
!>
!> Free field (BOUNDARY FF, zones_ffield): on the lateral edges (|n_x| >
!> |n_y|) of a point tied to the free field the dashpots act on the velocity
!> relative to the free field's, v - v_f (manual Section 3.8.2.3, Eq. 36);
!> `vfx`, `vfy` are zero for every other point.
!>
!> A model without viscous points does no work here (viscous_prepare returns
!> at once and viscous_step loops over nothing). Geometry (normals, half
!> lengths) is taken at the start of each CYCLE.
module zones_viscous
   use core_forces, only: add_rigid_force
   use core_kinds, only: wp, ip
   use model_properties, only: prop_bulk, prop_density, prop_shear
   use core_error, only: error_t, set_error
   use core_output, only: fmt_real
   use model_geometry, only: geometry_t
   use model_materials, only: material_table_t
   use model_boundary, only: boundary_t, bc_velocity, vis_x, vis_y
   use zones_boundary_setup, only: block_grid_t, block_grid_build, corner_free_sides
   implicit none
   private
   public :: viscous_work_t, viscous_prepare, viscous_step, viscous_fit_masses
   public :: boundary_point_live

   type :: viscous_work_t
      integer(ip) :: n = 0                          !< viscous points
      integer(ip), allocatable :: point(:)          !< their index in the boundary list
      real(wp), allocatable :: rcp(:), rcs(:)       !< rho c_p, rho c_s
      integer, allocatable :: nedge(:)              !< viscous half edges (0..2)
      real(wp), allocatable :: enx(:, :), eny(:, :) !< (2, n) outward unit normals
      real(wp), allocatable :: ehl(:, :)            !< (2, n) half lengths
      real(wp) :: dt_max = huge(1.0_wp)             !< stable step of the dashpots
      !> velocity of the far field the dashpots act against: 0, or the free
      !> field's at points tied to it (BOUNDARY FF, set each step by zones_ffield)
      real(wp), allocatable :: vfx(:), vfy(:)
      !> stable step of the free-field column (zones_ffield), huge without one
      real(wp) :: dt_ffield = huge(1.0_wp)
   end type viscous_work_t

contains

   !> Viscous points, their far-field impedances and half edges, and the
   !> largest stable step `vw%dt_max` given the inertial masses of the
   !> gridpoints (`gmass`, indexed by gridpoint) and blocks (`bmass`,
   !> `binertia`, indexed by block). Fails, naming the point, when a viscous
   !> point has no usable far-field material.
   subroutine viscous_prepare(vw, bnd, geo, mats, gmass, bmass, binertia, error)
      type(viscous_work_t), intent(inout) :: vw
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      type(material_table_t), intent(in) :: mats
      real(wp), intent(in) :: gmass(:), bmass(:), binertia(:)
      type(error_t), allocatable, intent(out) :: error
      type(block_grid_t) :: grid
      integer(ip), allocatable :: map(:)
      real(wp), allocatable :: csum(:), crr(:)
      integer(ip) :: i, k, c, n, b, g
      integer :: m
      real(wp) :: rho, kb, gs, cmax, r2
      logical :: fp, fn
      character(len=240) :: text

      vw%n = 0
      vw%dt_max = huge(1.0_wp)
      if (bnd%n == 0) return
      if (.not. allocated(bnd%vis)) return
      n = 0
      do i = 1, bnd%n
         if (bnd%vis(i) /= 0 .and. boundary_point_live(bnd, geo, i)) n = n + 1
      end do
      if (n == 0) return

      if (allocated(vw%point)) deallocate (vw%point, vw%rcp, vw%rcs, vw%nedge, vw%enx, vw%eny, &
                                           vw%ehl, vw%vfx, vw%vfy)
      allocate (vw%point(n), vw%rcp(n), vw%rcs(n), vw%nedge(n), vw%enx(2, n), vw%eny(2, n), &
                vw%ehl(2, n), vw%vfx(n), vw%vfy(n))
      vw%vfx = 0.0_wp
      vw%vfy = 0.0_wp
      allocate (map(max(1_ip, geo%corners%n)))
      map = 0
      k = 0
      do i = 1, bnd%n
         if (bnd%vis(i) == 0 .or. .not. boundary_point_live(bnd, geo, i)) cycle
         k = k + 1
         vw%point(k) = i
         map(bnd%corner(i)) = k
      end do

      do k = 1, n
         i = vw%point(k)
         c = bnd%corner(i)
         m = bnd%vmat(i)
         if (m < 1) then
            write (text, '(a,i0,5a)') 'CYCLE: boundary corner ', c, ' at (', &
               fmt_real(geo%corners%x(c), 12, 5), ', ', fmt_real(geo%corners%y(c), 12, 5), &
               ') is viscous (BOUNDARY XVISC / YVISC) '// &
               'but has no far-field material: give BOUNDARY MAT n for it'
            call set_error(error, trim(text))
            return
         end if
         rho = 0.0_wp; kb = 0.0_wp; gs = 0.0_wp
         if (m <= mats%nmat) then
            rho = mats%get(m, prop_density)
            kb = mats%get(m, prop_bulk)
            gs = mats%get(m, prop_shear)
         end if
         if (.not. (rho > 0.0_wp .and. kb >= 0.0_wp .and. gs > 0.0_wp)) then
            write (text, '(a,i0,a,i0,a)') 'CYCLE: the far-field material ', m, &
               ' of the viscous boundary (BOUNDARY MAT ', m, ') needs DENSITY > 0, '// &
               'BULK >= 0 and SHEAR > 0 (PROPERTY MAT n DENSITY .. BULK .. SHEAR ..)'
            call set_error(error, trim(text))
            return
         end if
         vw%rcp(k) = sqrt(rho*(kb + 4.0_wp*gs/3.0_wp))
         vw%rcs(k) = sqrt(rho*gs)
      end do

      call block_grid_build(geo, grid)
      do k = 1, n
         c = bnd%corner(vw%point(k))
         vw%nedge(k) = 0
         call corner_free_sides(geo, grid, c, fp, fn)
         if (fn) call add_edge(k, c, geo%corners%next(c))
         if (fp) call add_edge(k, geo%corners%prev(c), c)
      end do

      ! stable step: c dt / m <= 1 per gridpoint; per rigid block for its
      ! translation (sum of c) and rotation (sum of c r^2 about the centroid)
      allocate (csum(max(1_ip, geo%blocks%n)), crr(max(1_ip, geo%blocks%n)))
      csum = 0.0_wp
      crr = 0.0_wp
      do k = 1, n
         c = bnd%corner(vw%point(k))
         cmax = max(vw%rcp(k), vw%rcs(k))*sum(vw%ehl(1:vw%nedge(k), k))
         if (cmax <= 0.0_wp) cycle
         g = geo%corners%gp(c)
         b = geo%corners%block(c)
         if (g > 0) then
            if (g <= size(gmass)) then
               if (gmass(g) > 0.0_wp) vw%dt_max = min(vw%dt_max, gmass(g)/cmax)
            end if
         else
            csum(b) = csum(b) + cmax
            r2 = (geo%corners%x(c) - geo%blocks%xc(b))**2 + (geo%corners%y(c) - geo%blocks%yc(b))**2
            crr(b) = crr(b) + cmax*r2
         end if
      end do
      do b = 1, geo%blocks%n
         if (csum(b) <= 0.0_wp .or. b > size(bmass)) cycle
         if (geo%blocks%fixed(b)) cycle
         if (bmass(b) > 0.0_wp) vw%dt_max = min(vw%dt_max, bmass(b)/csum(b))
         if (crr(b) > 0.0_wp .and. binertia(b) > 0.0_wp) &
            vw%dt_max = min(vw%dt_max, binertia(b)/crr(b))
      end do
      vw%n = n

   contains

      !> The free edge a -> b (clockwise) next to point k, if its other end
      !> is viscous too.
      subroutine add_edge(kk, a, bb)
         integer(ip), intent(in) :: kk, a, bb
         integer(ip) :: other
         real(wp) :: dx, dy, l
         other = merge(bb, a, bnd%corner(vw%point(kk)) == a)
         if (map(other) == 0) return
         dx = geo%corners%x(bb) - geo%corners%x(a)
         dy = geo%corners%y(bb) - geo%corners%y(a)
         l = hypot(dx, dy)
         if (l <= 0.0_wp) return
         vw%nedge(kk) = vw%nedge(kk) + 1
         ! outward normal of a clockwise edge: (-dy, dx) / l
         vw%enx(vw%nedge(kk), kk) = -dy/l
         vw%eny(vw%nedge(kk), kk) = dx/l
         vw%ehl(vw%nedge(kk), kk) = 0.5_wp*l
      end subroutine add_edge
   end subroutine viscous_prepare

   !> MSCALE PART tdel (manual Section 4.5: "density scaling only to those
   !> zones necessary to achieve time-step tdel"): a gridpoint of a viscous
   !> point too light for its dashpots at tdel (c tdel / m > 1) gets the
   !> inertial mass c tdel, as the zones' partial scaling raises the masses
   !> too light for their stiffness. Rigid blocks keep theirs. The caller
   !> runs viscous_prepare again for the new bound.
   subroutine viscous_fit_masses(vw, bnd, geo, gmass, tdel)
      type(viscous_work_t), intent(in) :: vw
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      real(wp), intent(inout) :: gmass(:)
      real(wp), intent(in) :: tdel
      integer(ip) :: k, g
      real(wp) :: cmax
      do k = 1, vw%n
         g = geo%corners%gp(bnd%corner(vw%point(k)))
         if (g < 1 .or. g > size(gmass)) cycle
         cmax = max(vw%rcp(k), vw%rcs(k))*sum(vw%ehl(1:vw%nedge(k), k))
         gmass(g) = max(gmass(g), cmax*tdel)
      end do
   end subroutine viscous_fit_masses

   !> Dashpot forces of one step into the gridpoint force sums (FDEF corners)
   !> or the block force and moment (rigid corners), from the current
   !> velocities.
   subroutine viscous_step(vw, bnd, geo)
      type(viscous_work_t), intent(in) :: vw
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(inout) :: geo
      integer(ip) :: k, i, c, b, g
      integer :: e
      real(wp) :: vx, vy, vn, fx, fy, nx, ny, hl, rx, ry, rvx, rvy
      associate (co => geo%corners, bl => geo%blocks, gp => geo%gridpoints)
         do k = 1, vw%n
            i = vw%point(k)
            c = bnd%corner(i)
            b = co%block(c)
            g = co%gp(c)
            if (g > 0) then
               vx = gp%vx(g)
               vy = gp%vy(g)
            else
               rx = co%x(c) - bl%xc(b)
               ry = co%y(c) - bl%yc(b)
               vx = bl%vx(b) - bl%vr(b)*ry
               vy = bl%vy(b) + bl%vr(b)*rx
            end if
            fx = 0.0_wp
            fy = 0.0_wp
            do e = 1, vw%nedge(k)
               nx = vw%enx(e, k)
               ny = vw%eny(e, k)
               hl = vw%ehl(e, k)
               ! relative to the far field's motion: the free field's on a
               ! lateral edge of a BOUNDARY FF point (zones_ffield), else rest
               rvx = vx
               rvy = vy
               if (abs(nx) > abs(ny)) then
                  rvx = vx - vw%vfx(k)
                  rvy = vy - vw%vfy(k)
               end if
               vn = rvx*nx + rvy*ny
               ! normal part rho c_p v_n n, shear part rho c_s (v - v_n n)
               fx = fx - hl*(vw%rcp(k)*vn*nx + vw%rcs(k)*(rvx - vn*nx))
               fy = fy - hl*(vw%rcp(k)*vn*ny + vw%rcs(k)*(rvy - vn*ny))
            end do
            if (iand(bnd%vis(i), vis_x) == 0 .or. bnd%ix(i) == bc_velocity) fx = 0.0_wp
            if (iand(bnd%vis(i), vis_y) == 0 .or. bnd%iy(i) == bc_velocity) fy = 0.0_wp
            if (g > 0) then
               gp%fx(g) = gp%fx(g) + fx
               gp%fy(g) = gp%fy(g) + fy
            else
               call add_rigid_force(bl%fx, bl%fy, bl%fm, b, rx, ry, fx, fy)
            end if
         end do
      end associate
   end subroutine viscous_step

   !> Boundary point i stands on a live corner of a live block (the VISC and
   !> FFIELD points of a block that was deleted or cut away are skipped).
   pure logical function boundary_point_live(bnd, geo, i) result(live)
      type(boundary_t), intent(in) :: bnd
      type(geometry_t), intent(in) :: geo
      integer(ip), intent(in) :: i
      integer(ip) :: c
      c = bnd%corner(i)
      live = .false.
      if (c < 1 .or. c > geo%corners%n) return
      if (.not. geo%corners%live(c)) return
      live = geo%blocks%live(geo%corners%block(c))
   end function boundary_point_live

end module zones_viscous
