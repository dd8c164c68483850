!> The contact record keeps only what the scene's physics uses (issue 23):
!> the dilation ridden up (joint_state_t%ud, 8 bytes a contact) exists only
!> once a contact group dilates (JDIL > 0) or takes JCONS 3. A dry rigid
!> wall without JDIL cycles, saves and restarts without it; a jointed block
!> with JDIL under inclined gravity slips, so ud is made as long as the
!> contact list and some contact's is positive; SAVE and RESTART bring the
!> same values back (0 tolerance: a restart is bit for bit). The live marks
!> of blocks, corners, contacts and domains and the blocks' FIX/FDEF/SDEF
!> flags are one byte each, and RESTART brings back as many live entities.
!> A contact keeps two feature ids (end1, end2) instead of four lists
!> corner1, corner2, edge1, edge2 of which two were 0: read through
!> contact_corner1 .. contact_edge2, each is non-zero exactly where the
!> contact's kind has that feature (1 corner-corner, 2 corner1-edge2, 3
!> edge1-corner2), names a corner of the block on that side, and comes back
!> the same from a save file (which keeps the four lists).
program test_contact_storage
   use core_kinds, only: wp, ip
   use commands_session, only: session_t
   use testing_session, only: session_new_quiet, session_lines
   use testing, only: check, testing_finish, delete_file
   use model_geometry, only: contact_corner1, contact_corner2, contact_edge1, contact_edge2
   implicit none

   type(session_t) :: session

   call test_dry_wall()
   call test_dilating_joints()
   call test_contact_ends()
   call delete_file('test_contact_storage_dry.sav')
   call delete_file('test_contact_storage_jdil.sav')
   call delete_file('test_contact_storage_ends.sav')
   call testing_finish()

contains

   subroutine run(text)
      character(len=*), intent(in) :: text
      call session_lines(session, [text])
   end subroutine run

   subroutine build(jdil)
      character(len=*), intent(in) :: jdil
      call session_new_quiet(session)
      call session_lines(session, [character(len=80) :: 'ROUND 0.01', 'BLOCK 0,0 0,6 6,6 6,0', &
                                   'JSET 30,0 20,0 0,0 1.3,0 0,0', 'JSET -60,0 20,0 0,0 1.7,0 0,0', &
                                   'PROP MAT=1 DENS=2500 JKN=1E9 JKS=1E9 JFRIC=0.2'//jdil, &
                                   'GRAV 4 -10', 'FIX -1,7 -1,0.6', 'DAMP 0.05 10'])
   end subroutine build

   subroutine test_dry_wall()
      integer :: nlive(4)
      call build('')
      call run('CYCLE 300')
      associate (ct => session%model%geometry%contacts)
         call check(ct%n > 20, 'dry: the blocks are in contact')
         call check(any(ct%state%fn(1:ct%n) > 0.0_wp), 'dry: the contacts carry load')
         call check(.not. allocated(ct%state%ud), 'dry: no dilation field without JDIL')
      end associate
      nlive = live_counts()
      call run('SAVE test_contact_storage_dry.sav')
      call run('RESTART test_contact_storage_dry.sav')
      call check(.not. allocated(session%model%geometry%contacts%state%ud), &
                 'dry: none after RESTART either')
      call check(all(live_counts() == nlive), 'dry: as many live blocks, corners, contacts, domains restored')
      associate (g => session%model%geometry)
         call check(all([storage_size(g%blocks%live), storage_size(g%blocks%fixed), storage_size(g%blocks%fdef), &
                         storage_size(g%blocks%sdef), storage_size(g%corners%live), storage_size(g%contacts%live), &
                         storage_size(g%domains%live), storage_size(g%gridpoints%live), &
                         storage_size(g%zones%live)] == 8), 'dry: the live marks and block flags are one byte')
      end associate
      call run('CYCLE 10')
      call check(.not. allocated(session%model%geometry%contacts%state%ud), &
                 'dry: none after more cycles')
   end subroutine test_dry_wall

   !> Live blocks, corners, contacts and domains of the session's model.
   function live_counts() result(n)
      integer :: n(4)
      associate (g => session%model%geometry)
         n = [count(g%blocks%live(1:g%blocks%n)), count(g%corners%live(1:g%corners%n)), &
              count(g%contacts%live(1:g%contacts%n)), count(g%domains%live(1:g%domains%n))]
      end associate
   end function live_counts

   subroutine test_dilating_joints()
      real(wp), allocatable :: ud(:)
      integer(ip) :: n
      call build(' JDIL=0.2')
      call run('CYCLE 600')
      associate (ct => session%model%geometry%contacts)
         call check(allocated(ct%state%ud), 'JDIL: the dilation field exists')
         if (.not. allocated(ct%state%ud)) return
         call check(size(ct%state%ud) == size(ct%live), 'JDIL: as long as the contact list')
         call check(any(ct%state%ud(1:ct%n) > 0.0_wp), 'JDIL: some joint rode up its asperities')
         n = ct%n
         ud = ct%state%ud(1:n)
      end associate
      call run('SAVE test_contact_storage_jdil.sav')
      call run('RESTART test_contact_storage_jdil.sav')
      associate (ct => session%model%geometry%contacts)
         call check(allocated(ct%state%ud), 'JDIL: restored')
         if (.not. allocated(ct%state%ud)) return
         call check(ct%n == n, 'JDIL: as many contacts restored')
         if (ct%n == n) call check(all(ct%state%ud(1:n) == ud), 'JDIL: the same ud restored')
      end associate
   end subroutine test_dilating_joints

   subroutine test_contact_ends()
      integer(ip), allocatable :: f(:, :)
      integer(ip) :: c, n, nbad, nkind(3)
      call build('')
      call run('CYCLE 300')
      associate (g => session%model%geometry, ct => session%model%geometry%contacts)
         n = ct%n
         call check(n > 20, 'ends: the blocks are in contact')
         allocate (f(4, n))
         nbad = 0
         nkind = 0
         do c = 1, n
            f(:, c) = [contact_corner1(ct, c), contact_corner2(ct, c), contact_edge1(ct, c), &
                       contact_edge2(ct, c)]
            if (.not. ct%live(c)) cycle
            if (ct%kind(c) >= 1 .and. ct%kind(c) <= 3) nkind(ct%kind(c)) = nkind(ct%kind(c)) + 1
            ! non-zero exactly where the kind has the feature
            if ((f(1, c) > 0) .neqv. (ct%kind(c) /= 3)) nbad = nbad + 1
            if ((f(2, c) > 0) .neqv. (ct%kind(c) /= 2)) nbad = nbad + 1
            if ((f(3, c) > 0) .neqv. (ct%kind(c) == 3)) nbad = nbad + 1
            if ((f(4, c) > 0) .neqv. (ct%kind(c) == 2)) nbad = nbad + 1
            ! each a corner of its own side's block
            if (.not. on_block(max(f(1, c), f(3, c)), ct%block1(c))) nbad = nbad + 1
            if (.not. on_block(max(f(2, c), f(4, c)), ct%block2(c))) nbad = nbad + 1
         end do
         call check(nbad == 0, 'ends: corners and edges where the kinds say, on their blocks')
         call check(all(nkind > 0), 'ends: corner-corner and both corner-edge kinds present')
      end associate
      call run('SAVE test_contact_storage_ends.sav')
      call run('RESTART test_contact_storage_ends.sav')
      associate (ct => session%model%geometry%contacts)
         call check(ct%n == n, 'ends: as many contacts restored')
         if (ct%n /= n) return
         nbad = 0
         do c = 1, n
            if (any(f(:, c) /= [contact_corner1(ct, c), contact_corner2(ct, c), contact_edge1(ct, c), &
                                contact_edge2(ct, c)])) nbad = nbad + 1
         end do
         call check(nbad == 0, 'ends: the same corners and edges restored')
      end associate
   end subroutine test_contact_ends

   !> Corner k is a live corner of block b.
   logical function on_block(k, b)
      integer(ip), intent(in) :: k, b
      associate (co => session%model%geometry%corners)
         on_block = .false.
         if (k < 1 .or. k > co%n) return
         on_block = co%live(k) .and. co%block(k) == b
      end associate
   end function on_block

end program test_contact_storage
