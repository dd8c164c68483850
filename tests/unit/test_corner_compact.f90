!> Dense corner ids (model_compact, issue 23): after every command the live
!> corners are 1..n in their old order, each keeps its position, rounding,
!> block and 1989 address, the rings stay closed, and every list that names
!> a corner (boundary points, histories, contacts) names the same corner by
!> its new id; a model whose boundary still holds a dead corner keeps its
!> holes; a save file with holes is compacted when restarted.
!> Reference: the model before the renumbering (the same corners in the same
!> order); tolerance: none (values are moved, not computed).
program test_corner_compact
   use core_kinds, only: wp, ip
   use commands_session, only: session_t
   use model_geometry, only: contact_corner1, contact_corner2, contact_edge1, contact_edge2
   use model_geometry, only: geometry_t, geometry_kill_block
   use model_compact, only: model_compact_corners
   use testing, only: check, check_equal, testing_finish, delete_file
   use testing_session, only: session_new_quiet, session_lines
   implicit none

   call test_delete_and_cut()
   call test_holder_keeps_holes()
   call test_restart_with_holes()
   call testing_finish()

contains

   !> A 6 x 6 wall with a bottom boundary and a history at its top corner:
   !> DELETE, a crack and a CYCLE keep the corners dense and the lists right.
   subroutine test_delete_and_cut()
      type(session_t) :: s
      real(wp), allocatable :: x0(:), y0(:), r0(:), bx(:), by(:)
      integer(ip), allocatable :: a0(:)
      integer(ip) :: nb
      call wall(s)
      call bound_xy(s, bx, by)
      call check(dense(s%model%geometry), 'set-up: corner ids dense after JSET')
      nb = 8
      call keep_other(s%model%geometry, nb, x0, y0, r0, a0)
      call session_lines(s, [character(len=40) :: 'DELETE BLOCK 8'])
      call check(s%nerrors == 0, 'DELETE accepted')
      call check(dense(s%model%geometry), 'DELETE: corner ids dense')
      call same_corners(s%model%geometry, x0, y0, r0, a0, 'DELETE')
      call check(rings_closed(s%model%geometry), 'DELETE: rings closed')
      call holders_right(s, bx, by, 'DELETE')
      ! cycling, then a cut of a block carrying contact forces
      call session_lines(s, [character(len=40) :: 'CYCLE 20', 'CRACK 0.5,2.2 1.5,2.2', &
                                                   'DELETE BLOCK 20', 'CYCLE 20'])
      call check(s%nerrors == 0, 'CYCLE, CRACK, DELETE, CYCLE accepted')
      call check(dense(s%model%geometry), 'after cycling: corner ids dense')
      call check(rings_closed(s%model%geometry), 'after cycling: rings closed')
      call holders_right(s, bx, by, 'after cycling')
   end subroutine test_delete_and_cut

   !> A boundary point on a block killed outside a command: no renumbering.
   subroutine test_holder_keeps_holes()
      type(session_t) :: s
      integer(ip) :: n, b
      logical :: done
      call wall(s)
      b = s%model%geometry%corners%block(s%model%bound%corner(1))
      n = s%model%geometry%corners%n
      call geometry_kill_block(s%model%geometry, b)
      call model_compact_corners(s%model, done)
      call check(.not. done, 'boundary point on a dead corner: not renumbered')
      call check_equal(s%model%geometry%corners%n, n, 'boundary point on a dead corner: ids kept')
   end subroutine test_holder_keeps_holes

   !> A file saved with dead corner ids (a block killed outside a command)
   !> restarts with the same live corners, dense.
   subroutine test_restart_with_holes()
      type(session_t) :: s
      real(wp), allocatable :: x0(:), y0(:), r0(:), bx(:), by(:)
      integer(ip), allocatable :: a0(:)
      character(len=*), parameter :: file = 'test_corner_compact.sav'
      call wall(s)
      call bound_xy(s, bx, by)
      call keep_other(s%model%geometry, 9_ip, x0, y0, r0, a0)
      call geometry_kill_block(s%model%geometry, 9_ip)
      call check(.not. dense(s%model%geometry), 'restart: holes before the save')
      call session_lines(s, [character(len=40) :: 'SAVE '//file, 'NEW', 'RESTART '//file])
      call check(s%nerrors == 0, 'restart: SAVE, NEW, RESTART accepted')
      call check(dense(s%model%geometry), 'restart: corner ids dense')
      call same_corners(s%model%geometry, x0, y0, r0, a0, 'restart')
      call check(rings_closed(s%model%geometry), 'restart: rings closed')
      call holders_right(s, bx, by, 'restart')
      call delete_file(file)
   end subroutine test_restart_with_holes

   subroutine wall(s)
      type(session_t), intent(out) :: s
      call session_new_quiet(s)
      call session_lines(s, [character(len=60) :: 'ROUND 0.01', 'BLOCK 0,0 0,6 6,6 6,0', &
                             'JSET 0,0 60,0 0,0 1,0 0,0', 'JSET 90,0 60,0 0,0 1,0 0.5,0', &
                             'PROP MAT=1 DENS=2500 JKN=1E10 JKS=1E10 JFRIC=0.5', &
                             'GRAV 0 -10', 'BOUND -0.1,6.1 -0.1,0.1 YVEL 0', 'HIST XDIS 6,6'])
      call check(s%nerrors == 0, 'wall: commands accepted')
   end subroutine wall

   logical function dense(g)
      type(geometry_t), intent(in) :: g
      dense = count(g%corners%live(1:g%corners%n)) == g%corners%n
   end function dense

   !> Position, rounding radius and address of every live corner not of block
   !> `nb`, in id order.
   subroutine keep_other(g, nb, x, y, r, a)
      type(geometry_t), intent(in) :: g
      integer(ip), intent(in) :: nb
      real(wp), allocatable, intent(out) :: x(:), y(:), r(:)
      integer(ip), allocatable, intent(out) :: a(:)
      logical, allocatable :: keep(:)
      integer(ip) :: n
      n = g%corners%n
      keep = g%corners%live(1:n) .and. g%corners%block(1:n) /= nb
      x = pack(g%corners%x(1:n), keep)
      y = pack(g%corners%y(1:n), keep)
      r = pack(g%corners%radius(1:n), keep)
      a = pack(g%corners%addr(1:n), keep)
   end subroutine keep_other

   subroutine same_corners(g, x, y, r, a, what)
      type(geometry_t), intent(in) :: g
      real(wp), intent(in) :: x(:), y(:), r(:)
      integer(ip), intent(in) :: a(:)
      character(len=*), intent(in) :: what
      integer(ip) :: n
      n = g%corners%n
      call check_equal(n, size(x, kind=ip), what//': the live corners left')
      if (n /= size(x)) return
      call check(all(g%corners%x(1:n) == x .and. g%corners%y(1:n) == y), &
                 what//': same positions in the same order')
      call check(all(g%corners%radius(1:n) == r), what//': same rounding')
      call check(all(g%corners%addr(1:n) == a), what//': same 1989 addresses')
   end subroutine same_corners

   !> Every live block's ring: ncorner steps along next return to the first,
   !> prev undoes next, every corner is the block's.
   logical function rings_closed(g) result(ok)
      type(geometry_t), intent(in) :: g
      integer(ip) :: b, c, k, nseen
      ok = .false.
      nseen = 0
      do b = 1, g%blocks%n
         if (.not. g%blocks%live(b)) cycle
         c = g%blocks%first_corner(b)
         do k = 1, g%blocks%ncorner(b)
            if (c < 1 .or. c > g%corners%n) return
            if (g%corners%block(c) /= b) return
            if (g%corners%prev(g%corners%next(c)) /= c) return
            c = g%corners%next(c)
            nseen = nseen + 1
         end do
         if (c /= g%blocks%first_corner(b)) return
      end do
      ok = nseen == g%corners%n
   end function rings_closed

   !> Boundary points on the bottom, the history's corner where it was put,
   !> contacts' corners live corners of their blocks.
   subroutine holders_right(s, bx, by, what)
      type(session_t), intent(in) :: s
      real(wp), intent(in) :: bx(:), by(:)
      character(len=*), intent(in) :: what
      integer(ip) :: i, c, nbad
      associate (g => s%model%geometry, bnd => s%model%bound, h => s%model%hist)
         nbad = 0
         call check_equal(bnd%n, size(bx, kind=ip), what//': boundary points kept')
         do i = 1, min(bnd%n, size(bx, kind=ip))
            c = bnd%corner(i)
            if (c < 1 .or. c > g%corners%n) then
               nbad = nbad + 1
            else if (abs(g%corners%x(c) - g%corners%ux(c) - bx(i)) > 1.0e-9_wp .or. &
                     abs(g%corners%y(c) - g%corners%uy(c) - by(i)) > 1.0e-9_wp) then
               nbad = nbad + 1
            end if
         end do
         call check_equal(nbad, 0_ip, what//': boundary points at their corners')
         c = h%entity(1)
         call check(c >= 1 .and. c <= g%corners%n, what//': history at a corner')
         if (c >= 1 .and. c <= g%corners%n) &
            call check(abs(g%corners%x(c) - g%corners%ux(c) - 6.0_wp) < 1.0e-9_wp .and. &
                       abs(g%corners%y(c) - g%corners%uy(c) - 6.0_wp) < 1.0e-9_wp, &
                       what//': history corner at (6, 6)')
         nbad = 0
         do i = 1, g%contacts%n
            if (.not. g%contacts%live(i)) cycle
            if (.not. corner_of(g, contact_corner1(g%contacts, i), g%contacts%block1(i))) &
               nbad = nbad + 1
            if (.not. corner_of(g, contact_edge1(g%contacts, i), g%contacts%block1(i))) &
               nbad = nbad + 1
            if (.not. corner_of(g, contact_corner2(g%contacts, i), g%contacts%block2(i))) &
               nbad = nbad + 1
            if (.not. corner_of(g, contact_edge2(g%contacts, i), g%contacts%block2(i))) &
               nbad = nbad + 1
         end do
         call check_equal(nbad, 0_ip, what//': contacts name live corners of their blocks')
      end associate
   end subroutine holders_right

   !> Where the corners of the boundary points were before any motion.
   subroutine bound_xy(s, bx, by)
      type(session_t), intent(in) :: s
      real(wp), allocatable, intent(out) :: bx(:), by(:)
      integer(ip) :: i, c
      allocate (bx(s%model%bound%n), by(s%model%bound%n))
      do i = 1, s%model%bound%n
         c = s%model%bound%corner(i)
         bx(i) = s%model%geometry%corners%x(c) - s%model%geometry%corners%ux(c)
         by(i) = s%model%geometry%corners%y(c) - s%model%geometry%corners%uy(c)
      end do
   end subroutine bound_xy

   !> k is 0 or a corner of block b.
   logical function corner_of(g, k, b)
      type(geometry_t), intent(in) :: g
      integer(ip), intent(in) :: k, b
      corner_of = k == 0
      if (k >= 1 .and. k <= g%corners%n) corner_of = g%corners%block(k) == b
   end function corner_of

end program test_corner_compact
