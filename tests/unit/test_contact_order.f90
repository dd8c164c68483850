!> Storage order of the contact list (issue 23): after a full rebuild the
!> contacts are numbered along a Hilbert curve through their first blocks'
!> centroids. References: the Hilbert curve of order k visits each cell of
!> the 2**k x 2**k grid once, consecutive cells sharing a side (D. Hilbert,
!> Math. Ann. 38, 1891); for the wall, the set of contacts and the domains
!> must be what the rebuild finds in any order (counted by hand: an n x n
!> wall of unit blocks has 2 contacts at each end of every joint stretch
!> between two blocks, 4 n (n - 1) in all, plus the length-0 contacts of
!> diagonal neighbours at each interior joint crossing).
program test_contact_order
   use core_kinds, only: wp, ip, i8
   use core_curve, only: hilbert_index, curve_keys
   use commands_session, only: session_t
   use contact_refresh, only: geometry_refresh
   use testing, only: check, check_equal, testing_finish
   use testing_session, only: session_new_quiet, session_lines
   implicit none

   call test_hilbert_cells()
   call test_wall_contacts_in_curve_order()
   call testing_finish()

contains

   !> Order 4: the 256 cells get the positions 0..255 once each, and cells
   !> one position apart share a side.
   subroutine test_hilbert_cells()
      integer, parameter :: k = 4, m = 2**k
      integer(i8) :: ix, iy, d
      integer :: cx(0:m*m - 1), cy(0:m*m - 1), seen(0:m*m - 1), j, nbad
      seen = 0
      do iy = 0, m - 1
         do ix = 0, m - 1
            d = hilbert_index(ix, iy, k)
            call check(d >= 0 .and. d < m*m, 'hilbert: position in range')
            if (d < 0 .or. d >= m*m) cycle
            seen(d) = seen(d) + 1
            cx(d) = int(ix)
            cy(d) = int(iy)
         end do
      end do
      call check(all(seen == 1), 'hilbert: every position once')
      nbad = 0
      do j = 1, m*m - 1
         if (abs(cx(j) - cx(j - 1)) + abs(cy(j) - cy(j - 1)) /= 1) nbad = nbad + 1
      end do
      call check_equal(nbad, 0, 'hilbert: consecutive cells share a side')
      call check(hilbert_index(0_i8, 0_i8, k) == 0, 'hilbert: starts at the origin')
   end subroutine test_hilbert_cells

   !> A 12 x 12 wall cut by two joint sets: contacts in curve order of their
   !> first blocks, all still there, and domains that name them.
   subroutine test_wall_contacts_in_curve_order()
      type(session_t) :: s
      real(wp), allocatable :: keys(:)
      integer(ip) :: n, c, nlive, nzero, nbad, d, q
      call session_new_quiet(s)
      call session_lines(s, [character(len=60) :: 'ROUND 0.01', 'BLOCK 0,0 0,12 12,12 12,0', &
                             'JSET 0,0 120,0 0,0 1,0 0,0', 'JSET 90,0 120,0 0,0 1,0 0,0'])
      call check(s%nerrors == 0, 'wall: commands accepted')
      call geometry_refresh(s%model%geometry)
      associate (g => s%model%geometry)
         n = g%contacts%n
         nlive = count(g%contacts%live(1:n))
         nzero = count(g%contacts%live(1:n) .and. g%contacts%length(1:n) <= 0.0_wp)
         call check_equal(nlive - nzero, 4*12*11, 'wall: contacts with a length, 4 n (n - 1)')
         call check_equal(nzero, 2*11*11, 'wall: length-0 contacts, two at each interior crossing')
         allocate (keys(n))
         call curve_keys(g%blocks%xc(g%contacts%block1(1:n)), g%blocks%yc(g%contacts%block1(1:n)), keys)
         nbad = 0
         do c = 2, n
            if (keys(c) < keys(c - 1)) nbad = nbad + 1
         end do
         call check_equal(nbad, 0, 'wall: contacts in curve order of their first blocks')
         ! every domain names live contacts whose side it is
         nbad = 0
         do d = 1, g%domains%n
            if (.not. g%domains%live(d)) cycle
            do q = g%domains%first(d), g%domains%first(d) + g%domains%count(d) - 1
               c = g%domains%ring(q)
               if (c < 1 .or. c > n) then
                  nbad = nbad + 1
               else if (.not. g%contacts%live(c) .or. &
                        (g%contacts%dom1(c) /= d .and. g%contacts%dom2(c) /= d)) then
                  nbad = nbad + 1
               end if
            end do
         end do
         call check_equal(nbad, 0, 'wall: domain rings name contacts that bound them')
      end associate
   end subroutine test_wall_contacts_in_curve_order

end program test_contact_order
