!> Running command lines in a test session and reading what they printed
!> (shared by the unit tests that drive the command interpreter).
module testing_session
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use model_zones, only: vfix_y
   use commands_session, only: session_t, session_init, session_execute_line
   use model_geometry, only: geometry_t, geometry_total_area, geometry_live_blocks
   use contact_kinematics, only: contact_geometry
   implicit none
   private
   public :: session_run, lines_contain, session_new_quiet, session_lines
   public :: rigid_kinetic_energy, held_top, held_top_mean, held_top_fy
   public :: smallest_gap, scene_log_t

   !> A random scene's deck as it is typed, for the failure report, and the
   !> failures by kind: the first three of a kind print the seed and the
   !> deck so far (test_stability_rings, test_stability_scenes_random).
   type :: scene_log_t
      integer :: seed = 0, ndeck = 0
      character(len=160) :: deck(40)
      integer :: nfail(8) = 0
   contains
      procedure :: start => scene_log_start
      procedure :: run => scene_log_run
      procedure :: fail => scene_log_fail
   end type scene_log_t

contains

   !> A new scene: its seed, an empty deck.
   subroutine scene_log_start(log, seed)
      class(scene_log_t), intent(inout) :: log
      integer, intent(in) :: seed
      log%seed = seed
      log%ndeck = 0
   end subroutine scene_log_start

   !> Type `text` into session `s` and keep it in the deck.
   subroutine scene_log_run(log, s, text)
      class(scene_log_t), intent(inout) :: log
      type(session_t), intent(inout) :: s
      character(len=*), intent(in) :: text
      log%ndeck = min(log%ndeck + 1, size(log%deck))
      log%deck(log%ndeck) = text
      call session_execute_line(s, text, 1)
   end subroutine scene_log_run

   !> Count a failure of kind `what`; the first three print why and the deck.
   subroutine scene_log_fail(log, what, why)
      class(scene_log_t), intent(inout) :: log
      integer, intent(in) :: what
      character(len=*), intent(in) :: why
      integer :: k
      log%nfail(what) = log%nfail(what) + 1
      if (log%nfail(what) > 3) return
      print '(a,i0,a)', 'seed ', log%seed, ': '//why//'; the deck so far:'
      do k = 1, log%ndeck
         print '(4x,a)', trim(log%deck(k))
      end do
   end subroutine scene_log_fail

   !> The smallest gap of the live contacts, gmin (negative: an overlap), and
   !> the mean block size sqrt(area / blocks) to judge it by.
   subroutine smallest_gap(geo, gmin, size)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(out) :: gmin, size
      integer(ip) :: c
      real(wp) :: gap, nx, ny, px, py
      gmin = huge(1.0_wp)
      do c = 1, geo%contacts%n
         if (.not. geo%contacts%live(c)) cycle
         call contact_geometry(geo, c, 0.0_wp, gap, nx, ny, px, py)
         gmin = min(gmin, gap)
      end do
      size = sqrt(geometry_total_area(geo)/real(max(1_ip, geometry_live_blocks(geo)), wp))
   end subroutine smallest_gap

   !> A fresh session that writes nothing to the screen.
   subroutine session_new_quiet(s)
      type(session_t), intent(out) :: s
      type(error_t), allocatable :: error
      call session_init(s, error)
      s%out%screen = .false.
   end subroutine session_new_quiet

   !> Execute the command lines in order (numbered from 1).
   subroutine session_lines(s, lines)
      type(session_t), intent(inout) :: s
      character(len=*), intent(in) :: lines(:)
      integer :: i
      do i = 1, size(lines)
         call session_execute_line(s, trim(lines(i)), i)
      end do
   end subroutine session_lines

   !> Run one command line in `session` (screen output off); `lines`
   !> receives every line it printed, in order.
   subroutine session_run(session, text, lines)
      type(session_t), intent(inout) :: session
      character(len=*), intent(in) :: text
      character(len=200), allocatable, intent(inout) :: lines(:)
      integer :: capture, ios, n
      character(len=200) :: line
      character(len=200), allocatable :: grown(:)
      open (newunit=capture, status='scratch', action='readwrite')
      session%out%screen = .false.
      call session%out%add_unit(capture)
      call session_execute_line(session, text, 1)
      call session%out%remove_unit(capture)
      rewind (capture)
      if (allocated(lines)) deallocate (lines)
      allocate (lines(16))
      n = 0
      do
         read (capture, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (n == size(lines)) then
            allocate (grown(2*n))
            grown(1:n) = lines(1:n)
            call move_alloc(grown, lines)
         end if
         n = n + 1
         lines(n) = line
      end do
      close (capture)
      lines = lines(1:n)
   end subroutine session_run

   !> Some line of `lines` contains `text`.
   pure logical function lines_contain(lines, text) result(found)
      character(len=*), intent(in) :: lines(:), text
      integer :: i
      found = .false.
      do i = 1, size(lines)
         if (index(lines(i), text) > 0) found = .true.
      end do
   end function lines_contain

   !> Kinetic energy of the live, free rigid blocks of the session's model
   !> (translation and rotation about the centroid).
   real(wp) function rigid_kinetic_energy(s) result(ke)
      type(session_t), intent(in) :: s
      integer(ip) :: b
      ke = 0.0_wp
      associate (bl => s%model%geometry%blocks)
         do b = 1, bl%n
            if (.not. bl%live(b) .or. bl%fixed(b)) cycle
            ke = ke + 0.5_wp*(bl%mass(b)*(bl%vx(b)**2 + bl%vy(b)**2) + bl%inertia(b)*bl%vr(b)**2)
         end do
      end associate
   end function rigid_kinetic_energy

   !> Is gridpoint g live, held in y (a prescribed y velocity) and, as first
   !> generated (y - uy), above `ymin`? The loaded top of a zoned specimen.
   logical function held_top(s, g, ymin)
      type(session_t), intent(in) :: s
      integer(ip), intent(in) :: g
      real(wp), intent(in) :: ymin
      associate (gp => s%model%geometry%gridpoints)
         held_top = gp%live(g) .and. iand(gp%vfix(g), vfix_y) /= 0 .and. gp%y(g) - gp%uy(g) > ymin
      end associate
   end function held_top

   !> Mean of `values` (one per gridpoint) over the held top (held_top).
   real(wp) function held_top_mean(s, values, ymin) result(m)
      type(session_t), intent(in) :: s
      real(wp), intent(in) :: values(:)
      real(wp), intent(in) :: ymin
      integer(ip) :: g, k
      m = 0.0_wp
      k = 0
      do g = 1, s%model%geometry%gridpoints%n
         if (.not. held_top(s, g, ymin)) cycle
         m = m + values(g)
         k = k + 1
      end do
      m = m/max(k, 1)
   end function held_top_mean

   !> Sum of the y forces on the held top: its reaction (the zone forces on
   !> the held gridpoints, as PRINT BOUNDARY FORCES).
   real(wp) function held_top_fy(s, ymin) result(f)
      type(session_t), intent(in) :: s
      real(wp), intent(in) :: ymin
      integer(ip) :: g
      f = 0.0_wp
      do g = 1, s%model%geometry%gridpoints%n
         if (held_top(s, g, ymin)) f = f + s%model%geometry%gridpoints%fy(g)
      end do
   end function held_top_fy

end module testing_session
