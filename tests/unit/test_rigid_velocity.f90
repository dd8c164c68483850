!> BOUNDARY XVEL / YVEL on corners of rigid blocks (UDEC manual (ICG1.5,
!> 1989), Section 4.5 BOUNDARY, "Velocity (Displacement) Boundary"; thermal
!> Case 4, Section 7.8.5, gives `bou ... yvel 0` over a rigid block):
!> engine_rigid_velocity. Closed forms, each exact for the scheme up to
!> round-off (tolerance 1e-9 relative unless stated):
!> * rollers: YVEL 0 at the two bottom corners of a 2 x 1 block (mass 2000)
!>   under gravity with XLOAD 100 at each: the block does not fall or turn
!>   (vy, w below 1e-9), slides with a = 200 / 2000: after N = 1000 steps of
!>   dt = 1, vx = a N, ux = a dt^2 N (N + 1) / 2 (the central-difference sum);
!>   the unbalanced force is the unheld load, 200;
!> * a prescribed translation: XVEL 0.01 at both left corners: vx = 0.01, w = 0,
!>   ux = 0.01 N dt after N steps;
!> * one corner pulled from rest, XVEL 1 at corner (0, 0) of a unit square
!>   (m = 1000, I = m / 6; the corner at ry = -0.5 from the centroid, the
!>   constraint vx - w ry = 1): the least-constraint (impulse) response
!>   vx = 1 / (1 + m ry^2 / I) = 0.4, w = -vx m ry / I = 1.2 after one step;
!> * a FIXed block stays where it is; XFREE lets the block go (its velocity
!>   stays, nothing holds it);
!> * a model without such a corner has no "block velocities" stage;
!> * rollers alone leave out the "boundaries" stage (nothing for it to do: a
!>   velocity on a rigid corner is held by the block velocities stage); a
!>   load on a boundary point brings it back.
!> Also (issue 22): HISTORY FUNCTION is refused, nothing recorded.
program test_rigid_velocity
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use commands_session, only: session_t, session_init
   use testing_session, only: session_run, lines_contain
   use testing, only: check, check_close, testing_finish
   use engine_stages, only: stage_list, stage_block_velocity, stage_boundaries
   implicit none

   type(session_t) :: session
   character(len=200), allocatable :: lines(:)

   call test_rollers()
   call test_translation()
   call test_corner_pull()
   call test_fixed_and_free()
   call test_history_function()
   call testing_finish()

contains

   subroutine run(text)
      character(len=*), intent(in) :: text
      call session_run(session, text, lines)
   end subroutine run

   logical function printed(text)
      character(len=*), intent(in) :: text
      printed = lines_contain(lines, text)
   end function printed

   subroutine fresh()
      type(error_t), allocatable :: error
      call session_init(session, error)
      call check(.not. allocated(error), 'session starts')
      call run('ROUND 0.001')
   end subroutine fresh

   subroutine test_rollers()
      real(wp) :: a
      call fresh()
      call run('BLOCK 0,0 0,1 2,1 2,0')
      call run('PROP MAT 1 DENS 1000')
      call run('SET GRAV 0 -10')
      call check(.not. any(stage_list(session%model) == stage_block_velocity), &
                 'no velocity on a rigid corner: no block velocities stage')
      call run('BOUND -1 3 -0.01 0.01 YVEL 0')
      call check(printed('constrains the motion of their block'), &
                 'BOUND YVEL on rigid corners: a note, not a refusal')
      call check(.not. any(stage_list(session%model) == stage_boundaries), &
                 'rollers alone on rigid corners: no boundaries stage')
      call run('BOUND -1 3 -0.01 0.01 XLOAD 100')
      call check(any(stage_list(session%model) == stage_block_velocity), &
                 'YVEL on a rigid corner: the block velocities stage runs')
      call check(any(stage_list(session%model) == stage_boundaries), &
                 'XLOAD on the rollers: the boundaries stage runs')
      call run('CYCLE 1000')
      a = 200.0_wp/2000.0_wp
      associate (bl => session%model%geometry%blocks)
         call check(abs(bl%vy(1)) < 1.0e-9_wp .and. abs(bl%vr(1)) < 1.0e-9_wp .and. &
                    abs(bl%uy(1)) < 1.0e-9_wp, 'rollers: the block neither falls nor turns')
         call check_close(bl%vx(1), a*1000.0_wp, 1.0e-9_wp, 'rollers: vx = a N dt')
         call check_close(bl%ux(1), a*1000.0_wp*1001.0_wp/2.0_wp, 1.0e-9_wp, &
                          'rollers: ux = a dt^2 N (N + 1) / 2')
      end associate
      call check(printed('max unbalanced force  2.0000E+02'), &
                 'rollers: the unbalanced force is the unheld load (200), not gravity')
   end subroutine test_rollers

   subroutine test_translation()
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('PROP MAT 1 DENS 1000')
      call run('SET GRAV 0 -10')
      call run('BOUND -0.01 0.01 -1 2 XVEL 0.01')
      call run('CYCLE 50')
      associate (bl => session%model%geometry%blocks)
         call check_close(bl%vx(1), 0.01_wp, 1.0e-9_wp, 'XVEL at two corners: vx = v')
         call check(abs(bl%vr(1)) < 1.0e-12_wp, 'XVEL at two corners: no rotation')
         call check_close(bl%ux(1), 0.01_wp*50.0_wp*session%model%mech%dt, 1.0e-9_wp, &
                          'XVEL at two corners: ux = v N dt')
         call check(bl%vy(1) < 0.0_wp, 'XVEL at two corners: the block still falls')
      end associate
   end subroutine test_translation

   subroutine test_corner_pull()
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('PROP MAT 1 DENS 1000')
      call run('BOUND -0.01 0.01 -0.01 0.01 XVEL 1')
      call run('CYCLE 1')
      associate (bl => session%model%geometry%blocks)
         call check_close(bl%vx(1), 0.4_wp, 1.0e-9_wp, 'corner pulled: vx = 0.4 (least constraint)')
         call check_close(bl%vr(1), 1.2_wp, 1.0e-9_wp, 'corner pulled: w = 1.2 (counterclockwise)')
      end associate
   end subroutine test_corner_pull

   subroutine test_fixed_and_free()
      real(wp) :: v
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      call run('PROP MAT 1 DENS 1000')
      call run('SET GRAV 0 -10')
      call run('FIX 0 1 0 1')
      call run('BOUND -0.01 0.01 -1 2 XVEL 0.01')
      call run('CYCLE 10')
      call check(session%model%geometry%blocks%ux(1) == 0.0_wp .and. &
                 session%model%geometry%blocks%uy(1) == 0.0_wp, 'a FIXed block stays fixed')
      call run('FREE 0 1 0 1')
      call run('CYCLE 10')
      call check(abs(session%model%geometry%blocks%vx(1) - 0.01_wp) < 1.0e-12_wp, &
                 'FREE: the velocity holds')
      call run('BOUND -1 0.5 -1e4 1e4 XFREE')
      v = session%model%geometry%blocks%vy(1)
      call run('CYCLE 10')
      call check(.not. any(stage_list(session%model) == stage_block_velocity), &
                 'XFREE: the stage is gone')
      call check(abs(session%model%geometry%blocks%vx(1) - 0.01_wp) < 1.0e-12_wp, &
                 'XFREE: the block keeps its velocity (nothing holds or pushes it)')
      call check(session%model%geometry%blocks%vy(1) < v, 'XFREE: the block still falls')
   end subroutine test_fixed_and_free

   !> Issue 22, the same list: HISTORY FUNCTION n (the 1989 user-written
   !> FPLHIS(n)) is refused with a message that says what to do instead, and
   !> the line records nothing (it was a placeholder that read 0).
   subroutine test_history_function()
      integer :: nerr
      call fresh()
      call run('BLOCK 0,0 0,1 1,1 1,0')
      nerr = session%nerrors
      call run('HISTORY XVEL 0 0 FUNCTION 1')
      call check(session%nerrors == nerr + 1, 'HISTORY FUNCTION: an error')
      call check(printed('FPLHIS(n) has no counterpart') .and. printed('Adding a history'), &
                 'HISTORY FUNCTION: the message names the alternative')
      call check(session%model%hist%n == 0, 'HISTORY FUNCTION: nothing on the line recorded')
      call check(.not. printed('not yet'), 'HISTORY FUNCTION is not "not yet"')
   end subroutine test_history_function

end program test_rigid_velocity
