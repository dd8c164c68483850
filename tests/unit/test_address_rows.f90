!> 1989 address bookkeeping without copies of the live corners and contacts
!> (issue 23; model_address, ia_table_t). References: UDEC manual (ICG1.5,
!> 1989), Section 6.1, pp. 6-2 to 6-9 (records of NVCR = 13 and NVCN = 32
!> words, freed records kept on a junk list, Fig. 6-5), and docs/geometry.md
!> "1989 addresses" (a re-created corner or contact keeps the record of the
!> one at its place). Exact integer checks throughout: addresses are counts.
!>
!> After a synchronisation the match tables of corners and contacts hold no
!> rows, only a mark per entity; a contact rebuild (UPCON) keeps the rows of
!> the contacts it overwrites until the next synchronisation gives the new
!> contacts the same records; a cut gives the corners re-made at the old
!> vertices their old records; a deleted block's corners go to the junk list.
program test_address_rows
   use core_kinds, only: wp, ip
   use commands_session, only: session_t
   use contact_refresh, only: geometry_refresh
   use contact_detection, only: contact_rebuild
   use model_address, only: address_sync, ak_corner, ak_contact, record_length
   use testing, only: check, check_equal, testing_finish
   use testing_session, only: session_new_quiet, session_lines
   implicit none

   type(session_t) :: s
   call session_new_quiet(s)
   call session_lines(s, [character(len=60) :: 'ROUND 0.01', 'BLOCK 0,0 0,6 6,6 6,0', &
                          'JSET 0,0 60,0 0,0 1,0 0,0', 'JSET 90,0 60,0 0,0 1,0 0,0'])
   call check(s%nerrors == 0, 'wall: commands accepted')
   call geometry_refresh(s%model%geometry)
   call address_sync(s%model%geometry)
   call test_no_rows_after_sync()
   call test_rebuild_keeps_records()
   call test_cut_keeps_corner_records()
   call test_deleted_corners_junked()
   call testing_finish()

contains

   !> Only marks, one per corner and contact of the lists, no rows.
   subroutine test_no_rows_after_sync()
      associate (g => s%model%geometry)
         call check_equal(g%ia%ntab(ak_corner), 0_ip, 'sync: no corner rows')
         call check_equal(g%ia%ntab(ak_contact), 0_ip, 'sync: no contact rows')
         call check_equal(int(size(g%ia%tab(ak_contact)%addr), ip), 0_ip, 'sync: contact table empty')
         call check_equal(g%ia%tab(ak_corner)%nsynced, g%corners%n, 'sync: a mark per corner')
         call check_equal(g%ia%tab(ak_contact)%nsynced, g%contacts%n, 'sync: a mark per contact')
         call check(count(g%ia%tab(ak_contact)%synced(1:g%contacts%n) == 1) == &
                    count(g%contacts%live(1:g%contacts%n)), 'sync: the live contacts marked')
      end associate
   end subroutine test_no_rows_after_sync

   !> UPCON: every contact of the new list takes the record of the old
   !> contact between the same blocks at the same place; no record is new.
   subroutine test_rebuild_keeps_records()
      integer(ip), allocatable :: b1(:), b2(:), addr(:)
      real(wp), allocatable :: x(:), y(:)
      integer(ip) :: n, c, k, nlive, mfree, nbad, nfound
      associate (g => s%model%geometry)
         n = g%contacts%n
         nlive = count(g%contacts%live(1:n))
         call check(nlive > 100, 'rebuild: the wall has contacts')
         b1 = pack(g%contacts%block1(1:n), g%contacts%live(1:n))
         b2 = pack(g%contacts%block2(1:n), g%contacts%live(1:n))
         x = pack(g%contacts%x(1:n), g%contacts%live(1:n))
         y = pack(g%contacts%y(1:n), g%contacts%live(1:n))
         addr = pack(g%contacts%addr(1:n), g%contacts%live(1:n))
         mfree = g%ia%mfree
         call contact_rebuild(g)
         call check_equal(g%ia%ntab(ak_contact), nlive, 'rebuild: a row kept per contact overwritten')
         call check_equal(g%ia%tab(ak_contact)%nsynced, 0_ip, 'rebuild: the marks go')
         call geometry_refresh(g)
         call address_sync(g)
         call check_equal(g%ia%ntab(ak_contact), 0_ip, 'rebuild: rows used up by the sync')
         call check_equal(g%ia%mfree, mfree, 'rebuild: no new record')
         call check_equal(count(g%contacts%live(1:g%contacts%n)), nlive, 'rebuild: the same contacts')
         nbad = 0
         do c = 1, g%contacts%n
            if (.not. g%contacts%live(c)) cycle
            nfound = 0
            do k = 1, nlive
               if (.not. ((b1(k) == g%contacts%block1(c) .and. b2(k) == g%contacts%block2(c)) .or. &
                          (b1(k) == g%contacts%block2(c) .and. b2(k) == g%contacts%block1(c)))) cycle
               if (abs(x(k) - g%contacts%x(c)) > 1.0e-9_wp .or. abs(y(k) - g%contacts%y(c)) > 1.0e-9_wp) cycle
               if (addr(k) == g%contacts%addr(c)) nfound = nfound + 1
            end do
            if (nfound /= 1) nbad = nbad + 1
         end do
         call check_equal(nbad, 0_ip, 'rebuild: each contact keeps the record of the one at its place')
      end associate
   end subroutine test_rebuild_keeps_records

   !> CRACK through a row of blocks: each cut block's ring is made anew; the
   !> corners at its old vertices keep their records (new ones only at the
   !> crack), and no two live corners share a record.
   subroutine test_cut_keeps_corner_records()
      integer(ip), allocatable :: addr(:)
      real(wp), allocatable :: x(:), y(:)
      integer(ip) :: n, c, k, nold, nbad, nnew
      logical :: held
      associate (g => s%model%geometry)
         n = g%corners%n
         addr = pack(g%corners%addr(1:n), g%corners%live(1:n))
         x = pack(g%corners%x(1:n), g%corners%live(1:n))
         y = pack(g%corners%y(1:n), g%corners%live(1:n))
         nold = size(addr, kind=ip)
         call session_lines(s, [character(len=60) :: 'CRACK -1,2.5 7,2.5'])
         call check(s%nerrors == 0, 'cut: accepted')
         call check(g%corners%n > n, 'cut: corners made anew')
         nbad = 0
         do k = 1, nold
            held = .false.
            do c = 1, g%corners%n
               if (.not. g%corners%live(c) .or. g%corners%addr(c) /= addr(k)) cycle
               held = abs(g%corners%x(c) - x(k)) < 1.0e-9_wp .and. abs(g%corners%y(c) - y(k)) < 1.0e-9_wp
            end do
            if (.not. held) nbad = nbad + 1
         end do
         call check_equal(nbad, 0_ip, 'cut: every old corner record held at its place')
         nnew = 0
         do c = 1, g%corners%n
            if (g%corners%live(c) .and. .not. any(addr == g%corners%addr(c))) nnew = nnew + 1
         end do
         ! 6 blocks cut: 4 corners each at the crack (2 crossings x 2 pieces)
         call check_equal(nnew, 24_ip, 'cut: new records only at the crack')
         nbad = 0
         do c = 1, g%corners%n
            if (.not. g%corners%live(c)) cycle
            if (count(g%corners%live(1:g%corners%n) .and. g%corners%addr(1:g%corners%n) == g%corners%addr(c)) &
                /= 1) nbad = nbad + 1
         end do
         call check_equal(nbad, 0_ip, 'cut: no record held twice')
      end associate
   end subroutine test_cut_keeps_corner_records

   !> DELETE one block: its record and its four corners' go to the junk list.
   subroutine test_deleted_corners_junked()
      integer(ip) :: njunk, ncorner_junk
      associate (g => s%model%geometry)
         njunk = g%ia%njunk
         ncorner_junk = count(g%ia%junk_len(1:njunk) == record_length(ak_corner))
         call session_lines(s, [character(len=60) :: 'DELETE 4.2,4.8 4.2,4.8'])
         call check(s%nerrors == 0, 'delete: accepted')
         call check_equal(count(g%ia%junk_len(1:g%ia%njunk) == record_length(ak_corner)) - ncorner_junk, 4, &
                          'delete: the four corners junked')
         call check_equal(g%ia%ntab(ak_corner), 0_ip, 'delete: no corner rows left')
      end associate
   end subroutine test_deleted_corners_junked

end program test_address_rows
