!> The edge frames of the contact pass (issue 23): edge_frames_compute must
!> give every corner the frame that edge_frame gives it from the corner
!> arrays, to the last bit (the same expressions), after cutting and DELETE
!> (which leave no dead corner id between commands: model_compact), and
!> give the same frames when the corners are shared among threads.
!> Reference: the frame's definition in contact_kinematics (unit vector
!> along the clockwise edge, the tangent points s0, s1 of the end circles;
!> UDEC manual (ICG1.5, 1989), Section 3.3, Fig 3-3d). Tolerance: none.
program test_edge_frames
   use core_kinds, only: wp, ip
   use commands_session, only: session_t
   use contact_refresh, only: geometry_refresh
   use contact_kinematics, only: edge_frames_compute, edge_frame
   use testing, only: check, check_equal, testing_finish
   use testing_session, only: session_new_quiet, session_lines
   implicit none

   call test_frames('small wall', 12, 1)
   ! more than 8000 corner ids: the corners are walked in 8 chunks
   call test_frames('large wall, 2 threads', 48, 2)
   call testing_finish()

contains

   !> An n x n wall cut by two joint sets, its blocks moved off the grid by a
   !> CYCLE and two of them deleted: corner ids dense, every corner's frame
   !> as edge_frame gives it.
   subroutine test_frames(what, n, nthreads)
      character(len=*), intent(in) :: what
      integer, intent(in) :: n, nthreads
      type(session_t) :: s
      real(wp), allocatable :: frame(:, :)
      real(wp) :: ux, uy, nx, ny, s0, s1
      real(wp), parameter :: unset = -7.0_wp
      integer(ip) :: e, nlive, nbad
      character(len=60) :: box, js1, js2
      write (box, '(a,i0,a,i0,a,i0,a,i0,a)') 'BLOCK 0,0 0,', n, ' ', n, ',', n, ' ', n, ',0'
      write (js1, '(a,i0,a)') 'JSET 0,0 ', 10*n, ',0 0,0 1,0 0,0'
      write (js2, '(a,i0,a)') 'JSET 90,0 ', 10*n, ',0 0,0 1,0 0.5,0'
      call session_new_quiet(s)
      call session_lines(s, [character(len=60) :: 'ROUND 0.01', box, js1, js2, &
                             'DELETE BLOCK 3', 'DELETE BLOCK 7', &
                             'PROP MAT=1 DENS=2500 JKN=1E10 JKS=1E10 JFRIC=0.5', &
                             'GRAV 0.5 -10', 'FIX -1,1000 -1,0.5', 'CYCLE 20'])
      call check(s%nerrors == 0, what//': commands accepted')
      call geometry_refresh(s%model%geometry)
      associate (g => s%model%geometry)
         allocate (frame(4, g%corners%n))
         frame = unset
         call edge_frames_compute(g, frame, nthreads)
         nlive = 0
         nbad = 0
         do e = 1, g%corners%n
            if (.not. g%corners%live(e)) cycle
            nlive = nlive + 1
            call edge_frame(g, e, ux, uy, nx, ny, s0, s1)
            if (.not. (frame(1, e) == ux .and. frame(2, e) == uy .and. frame(3, e) == s0 .and. &
                       frame(4, e) == s1)) nbad = nbad + 1
         end do
         ! the cutting and the deletions killed corners; their ids are gone
         call check(nlive > 4*(n*n - 2), what//': the wall''s corners')
         call check_equal(nlive, g%corners%n, what//': corner ids dense (no dead one)')
         call check_equal(nbad, 0_ip, what//': every corner''s frame is edge_frame''s')
      end associate
   end subroutine test_frames

end program test_edge_frames
