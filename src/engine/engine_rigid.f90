!> Rigid-block motion (manual Section 3.4, Eqs. 20-25, with the viscous
!> damping of Eq. 28): masses and moments of inertia, the central-difference
!> update of centroid and angular velocities, and the new block positions
!> (corners and rounding circles move with their block).
module engine_rigid
   use core_kinds, only: wp, ip, l1
   use core_motion, only: motion_step_t, motion_result_t
   use model_properties, only: prop_density
   use core_error, only: error_t, set_error
   use core_output, only: format_real
   use model_geometry, only: geometry_t
   use model_materials, only: material_table_t
   use engine_sdef, only: sdef_work_t
   !$ use omp_lib, only: omp_get_max_threads
   implicit none
   private
   public :: rigid_masses, rigid_motion, motion_work_t, motion_save, motion_restore

   !> Fewer live blocks than this move on one thread whatever OMP_NUM_THREADS
   !> says; without OMP_NUM_THREADS in the environment, one thread (as the
   !> zone and contact passes).
   integer(ip), parameter :: thread_min_blocks = 1000

   !> Copies of the moving state taken during each step, so that a step that
   !> fails (contact overlap too great, a non-finite force) can be undone
   !> exactly. Rigid blocks are copied by rigid_motion as it moves them (the
   !> values are at hand there; a block that does not move keeps its corners,
   !> which are then not copied), gridpoints likewise by gridpoint_motion
   !> (zones_mechanics) into `g`; the corners of FDEF blocks by motion_save
   !> before the step.
   !> The corners of rigid blocks (six values each, most of the copies) are
   !> copied only when the step could fail after moving them. The step checks
   !> that before it moves a corner: with `may_skip` (the CYCLE's stages can
   !> fail only by a contact overlap: no gridpoints, SDEF blocks, structures,
   !> cables, fluid, free field or velocity-held blocks, a geometry update
   !> every step), the previous step's contact pass found no overlap beyond
   !> `screen` x OVTOL (`safe`), and this step moves no block point further
   !> than `reach` x OVTOL, no contact can close by more than the rest of
   !> OVTOL in this step (a gap changes by at most the travel of the two
   !> points nearest it; `reach` leaves a factor 4 for the lever of an edge
   !> that turns and the rounding of the arithmetic), so no overlap can fail
   !> it and its corners are moved without copies.
   type :: motion_work_t
      integer(ip) :: nb = 0, nc = 0
      !> rigid_motion has copied the rigid blocks of this step
      logical :: rigid_saved = .false.
      !> gridpoint_motion has copied the gridpoints of this step into g
      logical :: grid_saved = .false.
      !> (6, blocks): vx vy vr fx fy fm before the velocity update, every step
      real(wp), allocatable :: b(:, :)
      !> (5, blocks): xc yc ux uy rot of a block rigid_motion moved, copied
      !> with its corners, so only in a step that copies corners (sized by
      !> corner_slots; issue 23: 40 bytes a block a step that cannot fail
      !> leaves out)
      real(wp), allocatable :: p(:, :)
      logical, allocatable :: moved(:)   !< (blocks): corners copied and moved this step
      !> (blocks): the copies of block b's corners are c(:, cslot(b) + k), k = 1 ..
      !> ncorner(b) in ring order: one slot per corner of a live block, not
      !> per corner id (cutting leaves about half the corner ids dead: 48 bytes
      !> each at 100k blocks)
      integer(ip), allocatable :: cslot(:)
      real(wp), allocatable :: c(:, :)   !< (6, corners of live blocks): x y rx ry ux uy
      real(wp), allocatable :: m_in(:), i_in(:)   !< inertial mass and moment (MSCALE)
      integer(ip) :: ng = 0
      real(wp), allocatable :: g(:, :)   !< (8, gridpoints): x y vx vy ux uy fx fy
      type(sdef_work_t) :: sd            !< simply-deformable blocks (engine_sdef)
      !> threads of rigid_motion (rigid_masses sets it); with more than one,
      !> each block's unbalanced force, kinetic energy change, damping energy
      !> and travel go to bterm(1:4, b) and one thread then sums them in block
      !> order, as the one-thread loop does: the same bits at any thread count
      integer :: nthreads = 1
      real(wp), allocatable :: bterm(:, :)
      !> the CYCLE's step can fail only by a contact overlap (cycle_run)
      logical :: may_skip = .false.
      !> the last contact pass found no overlap beyond screen x ovtol
      logical :: safe = .false.
      !> rigid_motion copied the corners of the blocks it moved this step
      logical :: corners_saved = .false.
      !> cslot and c are ready for this step's corner copies
      logical :: slots_ready = .false.
      real(wp) :: ovtol = 0.0_wp     !< the CYCLE's overlap tolerance (cycle_run)
      !> the largest distance of a corner or rounding centre of a rigid block
      !> from its centroid (rigid_masses), distances kept by rigid motion
      real(wp) :: rmax = 0.0_wp
      !> per chunk of a threaded rigid_motion: the largest translation and turn
      real(wp), allocatable :: reach_t(:, :)
   end type motion_work_t

   !> See motion_work_t: a contact pass flags overlaps beyond screen x OVTOL
   !> (bigger ones still fail the step), and a step whose block points move
   !> at most reach x OVTOL needs no corner copies after a pass without
   !> flags: 0.25 + 2 x 4 x 0.0625 = 0.75 of OVTOL at most.
   real(wp), parameter, public :: overlap_screen = 0.25_wp
   real(wp), parameter :: reach = 0.0625_wp

contains

   include 'core_damping.inc'

   !> Mass = density * area and polar moment of inertia about the centroid
   !> of every live block; inertial values (work%m_in, i_in) are the block
   !> mass `bcmass` (if 0: the average block mass) for all blocks when mass
   !> scaling is on, the moment scaled by the same ratio. A free block
   !> without density is an error.
   subroutine rigid_masses(geo, mats, mscale, bcmass, work, error)
      type(geometry_t), intent(inout) :: geo
      type(material_table_t), intent(in) :: mats
      logical, intent(in) :: mscale
      real(wp), intent(in) :: bcmass
      type(motion_work_t), intent(inout) :: work
      type(error_t), allocatable, intent(out) :: error
      integer(ip) :: b, k, c, q, nlive
      real(wp) :: rho, x1, y1, x2, y2, cr, j, mavg
      integer :: k32
      character(len=200) :: msg
      work%nthreads = 1
      call get_environment_variable('OMP_NUM_THREADS', status=k32)
      if (k32 == 0) then
         !$ work%nthreads = omp_get_max_threads()
      end if
      if (count(geo%blocks%live(1:geo%blocks%n)) < thread_min_blocks) work%nthreads = 1
      if (allocated(work%bterm)) deallocate (work%bterm)
      if (allocated(work%reach_t)) deallocate (work%reach_t)
      if (work%nthreads > 1) allocate (work%bterm(4, geo%blocks%n), work%reach_t(2, 4*work%nthreads))
      work%rmax = 0.0_wp
      if (allocated(work%m_in)) then
         if (size(work%m_in) < geo%blocks%n) deallocate (work%m_in, work%i_in)
      end if
      if (.not. allocated(work%m_in)) allocate (work%m_in(max(1_ip, geo%blocks%n)), &
                                                work%i_in(max(1_ip, geo%blocks%n)))
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         rho = mats%get(geo%blocks%material(b), prop_density)
         if (rho <= 0.0_wp .and. .not. geo%blocks%fixed(b)) then
            write (msg, '(a,i0,5a,i0,a)') 'CYCLE: block ', b, ' (centroid ', &
               format_real(geo%blocks%xc(b)), ', ', format_real(geo%blocks%yc(b)), &
               ') has no mass: give PROPERTY MAT=', &
               geo%blocks%material(b), ' DENSITY=..'
            call set_error(error, trim(msg))
            return
         end if
         ! second moment of the polygon about its centroid (coordinates
         ! relative to the centroid; clockwise ring, hence the sign)
         j = 0.0_wp
         c = geo%blocks%first_corner(b)
         do k = 1, geo%blocks%ncorner(b)
            q = geo%corners%next(c)
            x1 = geo%corners%x(c) - geo%blocks%xc(b)
            y1 = geo%corners%y(c) - geo%blocks%yc(b)
            x2 = geo%corners%x(q) - geo%blocks%xc(b)
            y2 = geo%corners%y(q) - geo%blocks%yc(b)
            cr = x1*y2 - x2*y1
            j = j + cr*(x1*x1 + x1*x2 + x2*x2 + y1*y1 + y1*y2 + y2*y2)
            if (.not. geo%blocks%fdef(b)) work%rmax = max(work%rmax, x1*x1 + y1*y1, &
               (geo%corners%rx(c) - geo%blocks%xc(b))**2 + (geo%corners%ry(c) - geo%blocks%yc(b))**2)
            c = q
         end do
         geo%blocks%mass(b) = rho*geo%blocks%area(b)
         geo%blocks%inertia(b) = rho*abs(j)/12.0_wp
         work%m_in(b) = geo%blocks%mass(b)
         work%i_in(b) = geo%blocks%inertia(b)
      end do
      ! (a hundredth more for the rounding of positions moved step after step)
      work%rmax = 1.01_wp*sqrt(work%rmax)
      if (.not. mscale) return
      ! mass scaling: every block gets bcmass (or the average block mass)
      mavg = bcmass
      if (mavg <= 0.0_wp) then
         mavg = 0.0_wp
         nlive = 0
         do b = 1, geo%blocks%n
            if (.not. geo%blocks%live(b)) cycle
            if (geo%blocks%fdef(b)) cycle
            mavg = mavg + geo%blocks%mass(b)
            nlive = nlive + 1
         end do
         if (nlive > 0) mavg = mavg/real(nlive, wp)
      end if
      if (mavg <= 0.0_wp) return
      do b = 1, geo%blocks%n
         if (.not. geo%blocks%live(b)) cycle
         if (geo%blocks%mass(b) <= 0.0_wp) cycle
         work%m_in(b) = mavg
         work%i_in(b) = geo%blocks%inertia(b)*mavg/geo%blocks%mass(b)
      end do
   end subroutine rigid_masses

   !> Before a step: room for the copies, and a copy of what rigid_motion and
   !> gridpoint_motion do not copy themselves (the corners of FDEF blocks).
   !> With `may_skip` the corner copies' slots wait for rigid_motion, which
   !> makes them only for a step that copies corners.
   subroutine motion_save(work, geo)
      type(motion_work_t), intent(inout) :: work
      type(geometry_t), intent(inout) :: geo    !< (only read)
      integer(ip) :: b
      if (.not. allocated(work%b)) then
         allocate (work%b(6, 0), work%moved(0), work%c(6, 0), work%cslot(0), work%p(5, 0))
      end if
      if (size(work%b, 2) < geo%blocks%n) then
         deallocate (work%b, work%moved, work%cslot)
         allocate (work%b(6, geo%blocks%n), work%moved(geo%blocks%n), work%cslot(geo%blocks%n))
      end if
      work%nb = geo%blocks%n
      work%nc = geo%corners%n
      work%rigid_saved = .false.
      work%grid_saved = .false.
      work%corners_saved = .false.
      work%slots_ready = .false.
      work%ng = geo%gridpoints%n
      if (.not. work%may_skip .or. work%ng > 0) call corner_slots(work, geo)
      if (.not. allocated(work%g)) allocate (work%g(8, 0))
      if (work%ng == 0) return
      associate (bl => geo%blocks)
         do b = 1, bl%n
            if (bl%live(b) .and. bl%fdef(b)) call block_corner_copies(work, geo, b, .false.)
         end do
      end associate
      if (size(work%g, 2) < work%ng) then
         deallocate (work%g)
         allocate (work%g(8, work%ng))
      end if
   end subroutine motion_save

   !> The corner copies' slots, block after block (one pass over the blocks
   !> a step that copies corners; blocks and their rings may change between
   !> steps), and room for them and for the moved blocks' positions (p).
   subroutine corner_slots(work, geo)
      type(motion_work_t), intent(inout) :: work
      type(geometry_t), intent(in) :: geo
      integer(ip) :: b, nslot
      nslot = 0
      do b = 1, geo%blocks%n
         work%cslot(b) = nslot
         if (geo%blocks%live(b)) nslot = nslot + geo%blocks%ncorner(b)
      end do
      if (size(work%c, 2) < nslot) then
         deallocate (work%c)
         allocate (work%c(6, nslot))
      end if
      if (size(work%p, 2) < geo%blocks%n) then
         deallocate (work%p)
         allocate (work%p(5, geo%blocks%n))
      end if
      work%slots_ready = .true.
   end subroutine corner_slots

   !> The moving state of block b's corners (ring order) copied into their
   !> slots work%c(:, cslot(b) + k) (`restore` false: motion_save), or the
   !> corners set back from them (`restore` true: motion_restore).
   pure subroutine block_corner_copies(work, geo, b, restore)
      type(motion_work_t), intent(inout) :: work
      type(geometry_t), intent(inout) :: geo
      integer(ip), intent(in) :: b
      logical, intent(in) :: restore
      integer(ip) :: c, k, s
      c = geo%blocks%first_corner(b)
      do k = 1, geo%blocks%ncorner(b)
         s = work%cslot(b) + k
         associate (co => geo%corners)
            if (restore) then
               co%x(c) = work%c(1, s); co%y(c) = work%c(2, s)
               co%rx(c) = work%c(3, s); co%ry(c) = work%c(4, s)
               co%ux(c) = work%c(5, s); co%uy(c) = work%c(6, s)
            else
               work%c(1, s) = co%x(c); work%c(2, s) = co%y(c)
               work%c(3, s) = co%rx(c); work%c(4, s) = co%ry(c)
               work%c(5, s) = co%ux(c); work%c(6, s) = co%uy(c)
            end if
         end associate
         c = geo%corners%next(c)
      end do
   end subroutine block_corner_copies

   !> Undo a step: the moving state as it was before the step (the copies of
   !> motion_save and rigid_motion).
   subroutine motion_restore(work, geo)
      type(motion_work_t), intent(inout) :: work    !< (only read)
      type(geometry_t), intent(inout) :: geo
      integer(ip) :: b, c
      associate (bl => geo%blocks)
         do b = 1, work%nb
            if (.not. bl%live(b)) cycle
            if (bl%fdef(b)) then
               if (work%ng == 0) cycle
            else
               if (.not. work%rigid_saved) cycle
               bl%vx(b) = work%b(1, b); bl%vy(b) = work%b(2, b)
               bl%vr(b) = work%b(3, b)
               bl%fx(b) = work%b(4, b); bl%fy(b) = work%b(5, b)
               bl%fm(b) = work%b(6, b)
               ! (a block that did not move kept its position; a step
               ! without corner copies cannot fail after moving them)
               if (.not. work%moved(b)) cycle
               if (.not. work%corners_saved) cycle
               bl%xc(b) = work%p(1, b); bl%yc(b) = work%p(2, b)
               bl%ux(b) = work%p(3, b); bl%uy(b) = work%p(4, b)
               bl%rot(b) = work%p(5, b)
            end if
            call block_corner_copies(work, geo, b, .true.)
         end do
      end associate
      if (.not. work%grid_saved) return
      associate (gp => geo%gridpoints)
         do c = 1, work%ng
            if (.not. gp%live(c)) cycle
            gp%x(c) = work%g(1, c); gp%y(c) = work%g(2, c)
            gp%vx(c) = work%g(3, c); gp%vy(c) = work%g(4, c)
            gp%ux(c) = work%g(5, c); gp%uy(c) = work%g(6, c)
            gp%fx(c) = work%g(7, c); gp%fy(c) = work%g(8, c)
         end do
      end associate
   end subroutine motion_restore

   !> One central-difference step of every live block (Eqs. 24, 25, 28):
   !> forces are the contact sums of the last step plus gravity (real mass)
   !> plus LOAD; accelerations use the inertial mass. Fixed blocks keep their
   !> velocities. Mass-proportional damping constant `alpha` [1/s]; local
   !> damping `aloc` (DAMP LOCAL, 0 otherwise): each of x, y and the rotation
   !> takes -aloc |F| sign(v) of its own unbalanced force.
   !> Returns in `res` the largest unbalanced force of a free block and that
   !> block, the kinetic energy before and after the velocity update summed
   !> as absolute per-block changes (`dke`), the energy taken by damping
   !> (`edamp`), and the largest travel of any block point.
   !> What it changes it first copies into `work` (motion_restore; sized by
   !> motion_save), the corners only when the step could still fail after
   !> moving them (motion_work_t): the velocities are updated first
   !> (rigid_velocity_kernel), then the blocks and corners moved
   !> (rigid_position_kernel), with the same arithmetic as one loop.
   !> The loops run with the arrays as explicit-shape dummies, so their
   !> addresses stay in registers across the cos/sin calls.
   subroutine rigid_motion(geo, work, ms, res)
      type(geometry_t), intent(inout) :: geo
      type(motion_work_t), intent(inout) :: work
      type(motion_step_t), intent(in) :: ms
      type(motion_result_t), intent(out) :: res
      integer :: t, nchunk
      integer(ip) :: b, ub
      real(wp) :: un, dk, de, tr, nobterm(4, 1), dmax, amax
      logical :: split, copy
      split = work%nthreads > 1 .and. allocated(work%bterm)
      ! blocks made since the CYCLE began (none in a rigid cycle): one thread
      if (split) split = size(work%bterm, 2) >= geo%blocks%n
      nchunk = 4*work%nthreads
      associate (bl => geo%blocks, co => geo%corners)
         if (.not. split) then
            call rigid_velocity_kernel(1_ip, bl%n, bl%live, bl%fdef, bl%fixed, bl%vx, &
                                       bl%vy, bl%vr, bl%fx, bl%fy, bl%fm, &
                                       bl%mass, bl%lx, bl%ly, work%m_in, work%i_in, work%b, &
                                       work%moved, ms, res%unbal, res%at, res%dke, &
                                       res%edamp, dmax, amax, .false., nobterm)
         else
            !$omp parallel do schedule(static) private(t, un, ub, dk, de)
            do t = 1, nchunk
               call rigid_velocity_kernel(1 + (t - 1)*bl%n/nchunk, t*bl%n/nchunk, bl%live, bl%fdef, &
                                          bl%fixed, bl%vx, bl%vy, bl%vr, &
                                          bl%fx, bl%fy, bl%fm, bl%mass, bl%lx, &
                                          bl%ly, work%m_in, work%i_in, work%b, work%moved, ms, &
                                          un, ub, dk, de, work%reach_t(1, t), &
                                          work%reach_t(2, t), .true., work%bterm)
            end do
            !$omp end parallel do
            dmax = maxval(work%reach_t(1, 1:nchunk))
            amax = maxval(work%reach_t(2, 1:nchunk))
         end if
         ! check before the corners move: copies only if the step could fail
         ! after this (motion_work_t; a NaN or infinite reach copies)
         copy = .not. (work%may_skip .and. work%safe .and. &
                       dmax + amax*work%rmax <= reach*work%ovtol)
         if (copy .and. .not. work%slots_ready) call corner_slots(work, geo)
         work%corners_saved = copy
         if (.not. split) then
            call rigid_position_kernel(1_ip, bl%n, bl%live, bl%fdef, bl%first_corner, bl%ncorner, &
                                       bl%xc, bl%yc, bl%vx, bl%vy, bl%vr, bl%ux, bl%uy, bl%rot, &
                                       work%moved, work%cslot, work%c, work%p, co%x, co%y, co%rx, &
                                       co%ry, co%ux, co%uy, co%next, ms%dt, res%travel, copy, .false., &
                                       nobterm)
         else
            !$omp parallel do schedule(static) private(t, tr)
            do t = 1, nchunk
               call rigid_position_kernel(1 + (t - 1)*bl%n/nchunk, t*bl%n/nchunk, bl%live, bl%fdef, &
                                          bl%first_corner, bl%ncorner, bl%xc, bl%yc, bl%vx, bl%vy, &
                                          bl%vr, bl%ux, bl%uy, bl%rot, work%moved, work%cslot, &
                                          work%c, work%p, co%x, co%y, co%rx, co%ry, co%ux, co%uy, &
                                          co%next, ms%dt, tr, copy, .true., work%bterm)
            end do
            !$omp end parallel do
            ! the one-thread loop's sums and maxima, in block order (res
            ! starts at zero)
            do b = 1, bl%n
               if (.not. bl%live(b)) cycle
               if (bl%fdef(b)) cycle
               if (.not. bl%fixed(b)) then
                  if (.not. (work%bterm(1, b) <= res%unbal)) then
                     res%unbal = work%bterm(1, b)
                     res%at = b
                  end if
                  res%dke = res%dke + work%bterm(2, b)
                  res%edamp = res%edamp + work%bterm(3, b)
               end if
               if (work%moved(b)) res%travel = max(res%travel, work%bterm(4, b))
            end do
         end if
      end associate
      work%rigid_saved = .true.
   end subroutine rigid_motion

   !> The velocity update of rigid_motion over blocks b0..n (each block's
   !> velocities and force sums copied into wb first, its force sums cleared
   !> after), `moved`
   !> set for a block with a velocity, and the largest translation `dmax`
   !> and turn `amax` of a block in the step. `split` (more than one
   !> thread): block b's unbalanced force, kinetic energy change and damping
   !> energy go to bterm(1:3, b) (the reductions' arguments, summed by
   !> rigid_motion in block order); unbal .. edamp are then meaningless.
   subroutine rigid_velocity_kernel(b0, n, live, fdef, fixed, vx, vy, vr, &
                                    bfx, bfy, bfm, mass, lx, ly, m_in, i_in, wb, moved, ms, &
                                    unbal, ubblock, dke, edamp, dmax, amax, split, bterm)
      integer(ip), intent(in) :: b0, n
      logical(l1), intent(in) :: live(*), fdef(*), fixed(*)
      real(wp), intent(inout) :: vx(*), vy(*), vr(*)
      real(wp), intent(inout) :: bfx(*), bfy(*), bfm(*)
      real(wp), intent(in) :: mass(*), lx(*), ly(*), m_in(*), i_in(*)
      real(wp), intent(inout) :: wb(6, *)
      logical, intent(inout) :: moved(*)
      type(motion_step_t), intent(in) :: ms
      real(wp), intent(out) :: unbal, dke, edamp, dmax, amax
      integer(ip), intent(out) :: ubblock
      logical, intent(in) :: split
      real(wp), intent(inout) :: bterm(4, *)
      integer(ip) :: b
      real(wp) :: fx, fy, fm, f, m, ai, vx0, vy0, vr0, k0, k1
      unbal = 0.0_wp
      ubblock = 0
      dke = 0.0_wp
      edamp = 0.0_wp
      dmax = 0.0_wp
      amax = 0.0_wp
      do b = b0, n
         if (.not. live(b)) cycle
         if (fdef(b)) cycle          ! moves by its gridpoints (zones_mechanics)
         vx0 = vx(b)
         vy0 = vy(b)
         vr0 = vr(b)
         wb(1, b) = vx0; wb(2, b) = vy0; wb(3, b) = vr0
         wb(4, b) = bfx(b); wb(5, b) = bfy(b); wb(6, b) = bfm(b)
         if (.not. fixed(b)) then
            m = m_in(b)
            ai = i_in(b)
            fx = bfx(b) + mass(b)*ms%grav(1) + lx(b)
            fy = bfy(b) + mass(b)*ms%grav(2) + ly(b)
            fm = bfm(b)
            f = sqrt(fx*fx + fy*fy)     ! not hypot (a libm call)
            if (split) then
               bterm(1, b) = f
            else if (.not. (f <= unbal)) then     ! also catches NaN
               unbal = f
               ubblock = b
            end if
            ! Eq. 28 with DAMP LOCAL per degree of freedom (core_damping.inc)
            vx(b) = damped_velocity(vx0, fx, m, ms%dt, ms%aloc, ms%con1, ms%con2)
            vy(b) = damped_velocity(vy0, fy, m, ms%dt, ms%aloc, ms%con1, ms%con2)
            vr(b) = damped_velocity(vr0, fm, ai, ms%dt, ms%aloc, ms%con1, ms%con2)
            k0 = 0.5_wp*(m*(vx0*vx0 + vy0*vy0) + ai*vr0*vr0)
            k1 = 0.5_wp*(m*(vx(b)**2 + vy(b)**2) + ai*vr(b)**2)
            if (split) then
               bterm(2, b) = abs(k1 - k0)
               bterm(3, b) = ms%alpha*ms%dt*0.25_wp*(m*((vx0 + vx(b))**2 + (vy0 + vy(b))**2) + &
                                               ai*(vr0 + vr(b))**2)
            else
               dke = dke + abs(k1 - k0)
               edamp = edamp + ms%alpha*ms%dt*0.25_wp*(m*((vx0 + vx(b))**2 + (vy0 + vy(b))**2) + &
                                                 ai*(vr0 + vr(b))**2)
            end if
         end if
         bfx(b) = 0.0_wp
         bfy(b) = 0.0_wp
         bfm(b) = 0.0_wp
         moved(b) = .not. (vx(b) == 0.0_wp .and. vy(b) == 0.0_wp .and. vr(b) == 0.0_wp)
         ! (a NaN reach counts as huge: that step copies)
         f = (abs(vx(b)) + abs(vy(b)))*ms%dt
         if (.not. (f <= dmax)) dmax = merge(f, huge(1.0_wp), f == f)
         f = abs(vr(b))*ms%dt
         if (.not. (f <= amax)) amax = merge(f, huge(1.0_wp), f == f)
      end do
   end subroutine rigid_velocity_kernel

   !> The move of rigid_motion over blocks b0..n: each block with `moved` set
   !> (rigid_velocity_kernel) moves by its velocity times dt and turns about
   !> its centroid, its corners and rounding centres with it (their copies
   !> into wc, and the block's position into wpos, first when `copy`). `split`: the travel of block b goes to
   !> bterm(4, b); `travel` is then meaningless.
   subroutine rigid_position_kernel(b0, n, live, fdef, first_corner, ncorner, xc, yc, vx, vy, vr, &
                                    ux, uy, rot, moved, cslot, wc, wpos, cx, cy, crx, cry, cux, cuy, next, &
                                    dt, travel, copy, split, bterm)
      integer(ip), intent(in) :: b0, n
      logical(l1), intent(in) :: live(*), fdef(*)
      logical, intent(in) :: moved(*)
      integer(ip), intent(in) :: first_corner(*), ncorner(*), next(*), cslot(*)
      real(wp), intent(inout) :: xc(*), yc(*), ux(*), uy(*), rot(*)
      real(wp), intent(in) :: vx(*), vy(*), vr(*)
      real(wp), intent(inout) :: wc(6, *), wpos(5, *)
      real(wp), intent(inout) :: cx(*), cy(*), crx(*), cry(*), cux(*), cuy(*)
      real(wp), intent(in) :: dt
      real(wp), intent(out) :: travel
      logical, intent(in) :: copy, split
      real(wp), intent(inout) :: bterm(4, *)
      integer(ip) :: b, k, c, s
      real(wp) :: dx, dy, dth, cs, sn, xo, yo, xn, yn, rad2
      travel = 0.0_wp
      do b = b0, n
         if (.not. live(b)) cycle
         if (fdef(b)) cycle
         if (.not. moved(b)) cycle
         dx = vx(b)*dt
         dy = vy(b)*dt
         dth = vr(b)*dt
         cs = cos(dth)
         sn = sin(dth)
         xo = xc(b)
         yo = yc(b)
         if (copy) then
            wpos(1, b) = xo; wpos(2, b) = yo
            wpos(3, b) = ux(b); wpos(4, b) = uy(b); wpos(5, b) = rot(b)
         end if
         xc(b) = xo + dx
         yc(b) = yo + dy
         ux(b) = ux(b) + dx
         uy(b) = uy(b) + dy
         rot(b) = rot(b) + dth
         rad2 = 0.0_wp
         c = first_corner(b)
         s = cslot(b)
         do k = 1, ncorner(b)
            if (copy) then
               ! save_corner written out (the hottest loop of the motion)
               s = s + 1
               wc(1, s) = cx(c); wc(2, s) = cy(c)
               wc(3, s) = crx(c); wc(4, s) = cry(c)
               wc(5, s) = cux(c); wc(6, s) = cuy(c)
            end if
            xn = xc(b) + cs*(cx(c) - xo) - sn*(cy(c) - yo)
            yn = yc(b) + sn*(cx(c) - xo) + cs*(cy(c) - yo)
            rad2 = max(rad2, (cx(c) - xo)**2 + (cy(c) - yo)**2)
            cux(c) = cux(c) + (xn - cx(c))
            cuy(c) = cuy(c) + (yn - cy(c))
            cx(c) = xn
            cy(c) = yn
            xn = xc(b) + cs*(crx(c) - xo) - sn*(cry(c) - yo)
            yn = yc(b) + sn*(crx(c) - xo) + cs*(cry(c) - yo)
            crx(c) = xn
            cry(c) = yn
            c = next(c)
         end do
         if (split) then
            bterm(4, b) = sqrt(dx*dx + dy*dy) + abs(dth)*sqrt(rad2)
         else
            travel = max(travel, sqrt(dx*dx + dy*dy) + abs(dth)*sqrt(rad2))
         end if
      end do
   end subroutine rigid_position_kernel

end module engine_rigid
