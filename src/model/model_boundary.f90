!> Boundary conditions of the block assembly (manual Section 4.5 BOUNDARY):
!> one entry per boundary point (a block corner on the free surface; for an
!> FDEF block the corner's gridpoint `corners%gp` carries the condition), and
!> the user multiplier tables read by BOUNDARY HREAD.
!>
!> Applied forces (manual Note under BOUNDARY): `fx`, `fy` are the totals;
!> `dfx`, `dfy` the increment given since the last CYCLE, applied during the
!> next CYCLE times the value of the point's history type and added into the
!> totals when that CYCLE ends. Forces act in the global x / y directions;
!> multipliers XMUL / YMUL scale forces and prescribed velocities.
!> Reading of the manual and the history formulas: docs/zones.md
!> ("Boundary conditions").
!>
!> Boundary stresses under SET FUP (the manual's default, "boundary force
!> update", Section 4.5 SET): BOUNDARY STRESS is kept as tractions, the
!> stress tensor (sxx, sxy, syy) acting on each of the two half edges next to
!> the point (`*_prev`: the half of the edge to the previous corner of its
!> block, `*_next`: to the next corner), taken once (zones_boundary_setup: at
!> the edge's third point from the point) when
!> the line is given; every step turns it into a
!> force with the edge's current length and outward normal (zones_boundary).
!> `d*` are the increments of the next CYCLE, as dfx / dfy. At a joint mouth
!> the side whose edge is the joint carries the stress of the gap segment to
!> the neighbouring block's corner (`end_prev`, `end_next`), so that the
!> loaded boundary stays a closed loop. Under SET -FUP
!> the stress becomes fixed forces in fx / fy, as XLOAD / YLOAD.
!>
!> Zone pressure sources (SET ZPRESS x y rad pz, `zpress_t` in `boundary_t%zp`):
!> the zones of each source are chosen when SET ZPRESS is given; each source
!> carries the history captured then (`h_next`: the latest BOUNDARY history
!> keyword since the last CYCLE). docs/zones.md ("Zone pressure").
module model_boundary
   use core_constants, only: two_pi
   use core_kinds, only: wp, ip, i8
   use core_arrays, only: grow_array, grow_lists
   implicit none
   private
   public :: boundary_t, boundary_table_t, boundary_add_point, boundary_index
   public :: boundary_history_value, boundary_has_traction, boundary_clear_tractions
   public :: zpress_t, zpress_add_source
   public :: bc_free, bc_stress, bc_viscous, bc_velocity
   public :: vis_x, vis_y
   public :: bh_constant, bh_linear, bh_sine, bh_cosine, bh_table1, bh_table2

   !> Condition codes per direction, as PRINT BOUNDARY STATE shows them.
   integer, parameter :: bc_free = 0, bc_stress = 1, bc_viscous = 3, bc_velocity = 4

   !> Viscous (non-reflecting) directions of a boundary point, bits of `vis`
   !> (BOUNDARY XVISC / YVISC). Kept apart from the condition codes: a stress
   !> and a viscous boundary may act on the same points (manual Section 5).
   integer, parameter :: vis_x = 1, vis_y = 2

   !> History types (BOUNDARY XHISTORY / YHISTORY / HISTORY).
   integer, parameter :: bh_constant = 0, bh_linear = 1, bh_sine = 2, bh_cosine = 3, &
                         bh_table1 = 11, bh_table2 = 12

   !> One user multiplier history (HREAD n file): np values at spacing dt,
   !> the first at time 0.
   type :: boundary_table_t
      character(len=:), allocatable :: heading
      integer(ip) :: np = 0
      real(wp) :: dt = 0.0_wp
      real(wp), allocatable :: values(:)
   end type boundary_table_t

   !> Zone pressure sources (SET ZPRESS). Source i: centre (x, y), radius rad,
   !> pressure pz (compression positive), history h / freq / tload (bh_*),
   !> nzone zones. The zones are the entries e = 1..nz with src(e) = i, stored
   !> in source order: zone(e) is the zone id.
   type :: zpress_t
      integer(ip) :: n = 0                      !< sources
      integer :: h_next = bh_constant           !< history for the next source
      real(wp) :: freq_next = 0.0_wp, tload_next = 0.0_wp
      real(wp), allocatable :: x(:), y(:), rad(:), pz(:)
      integer, allocatable :: h(:)
      real(wp), allocatable :: freq(:), tload(:)
      integer(ip), allocatable :: nzone(:)
      integer(ip) :: nz = 0                     !< (zone, source) entries
      integer(ip), allocatable :: zone(:), src(:)
   end type zpress_t

   type :: boundary_t
      integer(ip) :: n = 0                      !< boundary points
      integer(ip) :: corners_seen = 0           !< corner high-water mark at the last BOUNDARY
      real(wp) :: t_start = 0.0_wp              !< problem time at the start of the CYCLE
      integer(ip), allocatable :: corner(:)     !< corner id
      integer, allocatable :: ix(:), iy(:)      !< condition codes (bc_*)
      real(wp), allocatable :: fx(:), fy(:)     !< total applied force
      real(wp), allocatable :: dfx(:), dfy(:)   !< increment for the next CYCLE
      integer, allocatable :: hx(:), hy(:)      !< history type of the increment (bh_*)
      real(wp), allocatable :: freqx(:), tloadx(:), freqy(:), tloady(:)   !< SINE / COSINE
      real(wp), allocatable :: xmul(:), ymul(:) !< multipliers (default 1)
      real(wp), allocatable :: vx(:), vy(:)     !< prescribed velocities (code 4)
      integer, allocatable :: vis(:)            !< viscous directions (vis_x, vis_y bits)
      integer, allocatable :: vmat(:)           !< far-field material (BOUNDARY MAT n), 0 none
      !> BOUNDARY FF: 1 the point is tied to the free field (model_ffield), 0 not
      integer, allocatable :: ff(:)
      !> SET FUP (default) / -FUP: BOUNDARY STRESS acts as tractions on the
      !> current boundary / as fixed forces (module header)
      logical :: fup = .true.
      !> boundary stress on the half edges next to the point: totals
      real(wp), allocatable :: sxx_prev(:), sxy_prev(:), syy_prev(:)
      real(wp), allocatable :: sxx_next(:), sxy_next(:), syy_next(:)
      !> and the increments for the next CYCLE (with the point's histories)
      real(wp), allocatable :: dsxx_prev(:), dsxy_prev(:), dsyy_prev(:)
      real(wp), allocatable :: dsxx_next(:), dsxy_next(:), dsyy_next(:)
      !> the far end of the loaded segment on each side: 0 for the block's own
      !> previous / next corner, else the corner of the neighbouring block
      !> across a joint mouth (zones_boundary_setup's boundary_mouth_sides)
      integer(ip), allocatable :: end_prev(:), end_next(:)
      type(boundary_table_t) :: table(2)        !< HREAD 1 and 2
      type(zpress_t) :: zp                      !< SET ZPRESS sources
   end type boundary_t

contains

   !> Index of corner `c` in the list, 0 if it is not a boundary point.
   pure integer(ip) function boundary_index(bnd, c) result(k)
      type(boundary_t), intent(in) :: bnd
      integer(ip), intent(in) :: c
      do k = 1, bnd%n
         if (bnd%corner(k) == c) return
      end do
      k = 0
   end function boundary_index

   !> Append corner `c` as a free boundary point.
   subroutine boundary_add_point(bnd, c, id)
      type(boundary_t), intent(inout) :: bnd
      integer(ip), intent(in) :: c
      integer(ip), intent(out) :: id
      if (.not. allocated(bnd%corner)) call grow(bnd, 64_ip)
      if (bnd%n >= size(bnd%corner)) call grow(bnd, 2_ip*size(bnd%corner))
      bnd%n = bnd%n + 1
      id = bnd%n
      bnd%corner(id) = c
      ! free, unloaded, with a constant history of multiplier 1
      bnd%ix(id) = bc_free; bnd%iy(id) = bc_free; bnd%vis(id) = 0; bnd%vmat(id) = 0; bnd%ff(id) = 0
      bnd%fx(id) = 0.0_wp; bnd%fy(id) = 0.0_wp; bnd%dfx(id) = 0.0_wp; bnd%dfy(id) = 0.0_wp
      bnd%vx(id) = 0.0_wp; bnd%vy(id) = 0.0_wp; bnd%xmul(id) = 1.0_wp; bnd%ymul(id) = 1.0_wp
      bnd%hx(id) = bh_constant; bnd%freqx(id) = 0.0_wp; bnd%tloadx(id) = 0.0_wp
      bnd%hy(id) = bh_constant; bnd%freqy(id) = 0.0_wp; bnd%tloady(id) = 0.0_wp
      call boundary_clear_tractions(bnd, id)
   end subroutine boundary_add_point

   !> Point i carries no boundary stress as tractions (totals, increments and
   !> the T-junction ends of its sides).
   subroutine boundary_clear_tractions(bnd, i)
      type(boundary_t), intent(inout) :: bnd
      integer(ip), intent(in) :: i
      bnd%sxx_prev(i) = 0.0_wp; bnd%sxy_prev(i) = 0.0_wp; bnd%syy_prev(i) = 0.0_wp
      bnd%sxx_next(i) = 0.0_wp; bnd%sxy_next(i) = 0.0_wp; bnd%syy_next(i) = 0.0_wp
      bnd%dsxx_prev(i) = 0.0_wp; bnd%dsxy_prev(i) = 0.0_wp; bnd%dsyy_prev(i) = 0.0_wp
      bnd%dsxx_next(i) = 0.0_wp; bnd%dsxy_next(i) = 0.0_wp; bnd%dsyy_next(i) = 0.0_wp
      bnd%end_prev(i) = 0; bnd%end_next(i) = 0
   end subroutine boundary_clear_tractions

   !> Does point i carry a boundary stress kept as tractions (total or increment)?
   pure logical function boundary_has_traction(bnd, i) result(has)
      type(boundary_t), intent(in) :: bnd
      integer(ip), intent(in) :: i
      has = bnd%sxx_prev(i) /= 0.0_wp .or. bnd%sxy_prev(i) /= 0.0_wp .or. &
            bnd%syy_prev(i) /= 0.0_wp .or. bnd%sxx_next(i) /= 0.0_wp .or. &
            bnd%sxy_next(i) /= 0.0_wp .or. bnd%syy_next(i) /= 0.0_wp .or. &
            bnd%dsxx_prev(i) /= 0.0_wp .or. bnd%dsxy_prev(i) /= 0.0_wp .or. &
            bnd%dsyy_prev(i) /= 0.0_wp .or. bnd%dsxx_next(i) /= 0.0_wp .or. &
            bnd%dsxy_next(i) /= 0.0_wp .or. bnd%dsyy_next(i) /= 0.0_wp
   end function boundary_has_traction

   !> Value of history `htype` at step k of a CYCLE of ncycles steps at
   !> problem time `time` (docs/zones.md): CONSTANT 1; LINEAR k/ncycles;
   !> SINE / COSINE sin / cos(2 pi freq s) for s = time - t_start <= tload,
   !> else 0; table n: linear interpolation at `time` (first value at time 0),
   !> 0 beyond the last value.
   pure real(wp) function boundary_history_value(bnd, htype, freq, tload, time, k, ncycles) &
      result(h)
      type(boundary_t), intent(in) :: bnd
      integer, intent(in) :: htype
      real(wp), intent(in) :: freq, tload, time
      integer(i8), intent(in) :: k, ncycles
      real(wp) :: s, u
      integer(ip) :: i
      select case (htype)
      case (bh_linear)
         h = 1.0_wp
         if (ncycles > 0) h = real(k, wp)/real(ncycles, wp)
      case (bh_sine, bh_cosine)
         s = time - bnd%t_start
         h = 0.0_wp
         if (s <= tload) then
            if (htype == bh_sine) then
               h = sin(two_pi*freq*s)
            else
               h = cos(two_pi*freq*s)
            end if
         end if
      case (bh_table1, bh_table2)
         h = 0.0_wp
         associate (t => bnd%table(htype - bh_table1 + 1))
            if (t%np < 1 .or. t%dt <= 0.0_wp .or. time < 0.0_wp) return
            u = time/t%dt
            if (u > real(t%np - 1, wp)) return
            if (t%np == 1) then
               h = t%values(1)
               return
            end if
            i = min(int(u, ip), t%np - 2_ip)
            u = u - real(i, wp)
            h = (1.0_wp - u)*t%values(i + 1) + u*t%values(i + 2)
         end associate
      case default
         h = 1.0_wp
      end select
   end function boundary_history_value

   !> Append a source at (x, y) of radius rad and pressure pz acting on the
   !> zones `zones(:)`, with the history h_next / freq_next / tload_next.
   subroutine zpress_add_source(zp, x, y, rad, pz, zones)
      type(zpress_t), intent(inout) :: zp
      real(wp), intent(in) :: x, y, rad, pz
      integer(ip), intent(in) :: zones(:)
      integer(ip) :: i, m, nzn
      if (.not. allocated(zp%x)) then
         m = 4
      else
         m = size(zp%x)
         if (zp%n >= m) m = 2_ip*m
      end if
      call grow_lists(zp%n, m, zp%x, zp%y, zp%rad, zp%pz, zp%freq, zp%tload)
      call grow_lists(zp%n, m, zp%h, zp%nzone)
      zp%n = zp%n + 1
      i = zp%n
      zp%x(i) = x; zp%y(i) = y; zp%rad(i) = rad; zp%pz(i) = pz
      zp%h(i) = zp%h_next; zp%freq(i) = zp%freq_next; zp%tload(i) = zp%tload_next
      zp%nzone(i) = size(zones, kind=ip)
      nzn = zp%nz + size(zones, kind=ip)
      m = 64
      if (allocated(zp%zone)) m = size(zp%zone)
      do while (m < nzn)
         m = 2_ip*m
      end do
      call grow_array(zp%zone, zp%nz, m)
      call grow_array(zp%src, zp%nz, m)
      zp%zone(zp%nz + 1:nzn) = zones
      zp%src(zp%nz + 1:nzn) = i
      zp%nz = nzn
   end subroutine zpress_add_source

   subroutine grow(b, m)
      type(boundary_t), intent(inout) :: b
      integer(ip), intent(in) :: m
      call grow_lists(b%n, m, b%fx, b%fy, b%dfx, b%dfy, b%freqx, b%tloadx, b%freqy, b%tloady, &
                      b%xmul, b%ymul, b%vx, b%vy, b%sxx_prev, b%sxy_prev, b%syy_prev, &
                           b%sxx_next)
      call grow_lists(b%n, m, b%sxy_next, b%syy_next, b%dsxx_prev, b%dsxy_prev, b%dsyy_prev, &
                      b%dsxx_next, b%dsxy_next, b%dsyy_next)
      call grow_lists(b%n, m, b%corner, b%ix, b%iy, b%hx, b%hy, b%vis, b%vmat, b%end_prev, &
                      b%end_next, b%ff)
   end subroutine grow

end module model_boundary
