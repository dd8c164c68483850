!> Domains on demand (issue 23, contact_domains' domain_release): a CYCLE of
!> a dry model (no FLUID) gives back the domain list, its ring and the
!> contacts' dom1/dom2, and they are built from the contacts of the moment
!> when something reads them. A model that gains FLUID after cycling dry must
!> get the domains and the flow of one that had them all along.
!>
!> Model: a 6 x 6 wall of unit blocks (two joint sets) on a held bottom row,
!> a block of the second row deleted: the blocks above it fall into the
!> hole under gravity, so contacts are broken and made during the first
!> CYCLE. Session A is dry for that CYCLE and is given FLUID after it;
!> session B is given the same FLUID (density only: no bulk modulus, no
!> pressure, no permeability, so the fluid neither bounds the step nor
!> loads a block) before it, so its domains are built at every CYCLE's
!> set-up and kept through the steps. Both then get a bulk modulus, steady
!> flow, joint permeability, a pressure boundary, and cycle again.
!> Reference: session B. Tolerance: none (same values to the last bit).
program test_domains_on_demand
   use core_kinds, only: wp, ip
   use commands_session, only: session_t
   use contact_domains, only: domains_released, domain_rebuild
   use testing, only: check, check_equal, testing_finish, delete_file
   use testing_session, only: session_new_quiet, session_lines
   implicit none

   character(len=70), parameter :: wall(*) = [character(len=70) :: 'ROUND 0.01', &
      'BLOCK 0,0 0,6 6,6 6,0', 'JSET 0,0 100,0 0,0 1,0 0,0', 'JSET 90,0 100,0 0,0 1,0 0.5,0', &
      'DELETE 2.9,3.1 1.4,1.6', &
      'PROP MAT=1 DENS=2500 JKN=1E9 JKS=1E9 JFRIC=0.3', &
      'GRAV 0 -10', 'DAMP AUTO', 'FIX -1,7 -1,0.9']
   character(len=70), parameter :: flow(*) = [character(len=70) :: 'FLUID DEN 1000 BULK 2E9', &
      'PROP JMAT=1 JPERM=100 AZERO=1E-4 ARES=1E-4', &
      'SET SFLOW', 'BOUND -0.1 0.1 -0.1 6.1 PP 2E4', 'CYCLE 100']

   call test_dry_then_fluid()
   call testing_finish()

contains

   subroutine test_dry_then_fluid()
      type(session_t) :: a, b
      integer(ip) :: n0, live0, nd, nc, ndiff
      call session_new_quiet(a)
      call session_lines(a, [character(len=70) :: wall, 'CYCLE 1'])
      n0 = a%model%geometry%contacts%n
      live0 = count(a%model%geometry%contacts%live(1:n0))
      call session_lines(a, [character(len=70) :: 'CYCLE 2500'])
      call check(a%nerrors == 0, 'commands accepted')
      call check(.not. allocated(a%model%fluid), 'A is dry')
      ! the test means something only if the dry CYCLE made or broke contacts
      call check(a%model%geometry%contacts%n /= n0 .or. &
                 count(a%model%geometry%contacts%live(1:a%model%geometry%contacts%n)) /= live0, &
                 'the falling blocks made or broke contacts')
      ! A's domains came back at the synchronisation after the CYCLE (a
      ! contact was made or broken since the last one)
      call check(.not. domains_released(a%model%geometry), &
                 'A''s domains were built for the address synchronisation')
      call check(all(a%model%geometry%contacts%dom1(1:a%model%geometry%contacts%n) > 0 .or. &
                     .not. a%model%geometry%contacts%live(1:a%model%geometry%contacts%n)), &
                 'every live contact of A has its domains')
      ! a CYCLE in which no contact changes leaves A's domains released
      call session_lines(a, [character(len=70) :: 'FIX -1,7 -1,7', 'CYCLE 2', 'FREE -1,7 0.95,7'])
      call check(domains_released(a%model%geometry), 'A''s domains given back by a quiet CYCLE')
      call check(.not. allocated(a%model%geometry%domains%ring), 'A''s ring given back')
      ! B: the same model with its domains built now, from the same contacts
      ! (as a model with a fluid part has them, built at its CYCLE's set-up)
      call session_new_quiet(b)
      b%model = a%model
      call domain_rebuild(b%model%geometry)
      call check(.not. domains_released(b%model%geometry), 'B has its domains')
      ! FLUID builds A's again; then both flow
      call session_lines(a, flow)
      call session_lines(b, flow)
      call check(a%nerrors == 0 .and. b%nerrors == 0, 'flow commands accepted')
      call check(allocated(a%model%fluid) .and. allocated(b%model%fluid), 'both have a fluid part')
      if (.not. (allocated(a%model%fluid) .and. allocated(b%model%fluid))) return
      call same_domains(a, b, 'after flow')
      nd = min(a%model%geometry%domains%n, b%model%geometry%domains%n)
      call check(nd > 0, 'domains to flow through')
      call check(any(a%model%fluid%p(1:nd) > 0.0_wp), 'the pressure boundary reached a domain')
      ndiff = count(a%model%fluid%p(1:nd) /= b%model%fluid%p(1:nd))
      call check_equal(ndiff, 0_ip, 'same domain pressures')
      nc = min(a%model%geometry%contacts%n, b%model%geometry%contacts%n, &
               a%model%fluid%nc, b%model%fluid%nc)
      ndiff = count(a%model%fluid%q(1:nc) /= b%model%fluid%q(1:nc)) + &
              count(a%model%geometry%contacts%state%fn(1:nc) /= b%model%geometry%contacts%state%fn(1:nc))
      call check_equal(ndiff, 0_ip, 'same flow rates and normal forces')
      call check(any(a%model%fluid%q(1:nc) /= 0.0_wp), 'water flows')
      call test_save_released()
   end subroutine test_dry_then_fluid

   !> SAVE of a dry model right after a quiet CYCLE (domains released): the
   !> domains are built for the file and every inner one has its record.
   subroutine test_save_released()
      type(session_t) :: c
      integer(ip) :: ninner, nrec, nd
      integer(ip), allocatable :: ring(:)
      call session_new_quiet(c)
      call session_lines(c, [character(len=70) :: wall, 'CYCLE 50'])
      call session_lines(c, [character(len=70) :: 'FIX -1,7 -1,7', 'CYCLE 2'])
      call check(domains_released(c%model%geometry), 'C''s domains given back by a quiet CYCLE')
      call session_lines(c, [character(len=70) :: 'SAVE test_domains_on_demand.sav'])
      call check(c%nerrors == 0, 'SAVE accepted')
      call check(.not. domains_released(c%model%geometry), 'SAVE built the domains')
      associate (dm => c%model%geometry%domains)
         ninner = count(dm%live(1:dm%n) .and. .not. dm%outer(1:dm%n))
         nrec = count(dm%live(1:dm%n) .and. .not. dm%outer(1:dm%n) .and. dm%addr(1:dm%n) > 0)
      end associate
      call check(ninner > 0, 'C has inner domains')
      call check_equal(nrec, ninner, 'every inner domain of C has its record')
      nd = c%model%geometry%domains%n
      ring = c%model%geometry%domains%ring(1:c%model%geometry%domains%nring)
      call session_lines(c, [character(len=70) :: 'CYCLE 2', 'RESTART test_domains_on_demand.sav'])
      call check(c%nerrors == 0, 'RESTART accepted')
      call check_equal(c%model%geometry%domains%n, nd, 'the file holds the domains')
      call check(.not. domains_released(c%model%geometry), 'restored with the domains')
      if (c%model%geometry%domains%nring == size(ring, kind=ip)) then
         call check(all(c%model%geometry%domains%ring(1:size(ring)) == ring), 'the same rings restored')
      else
         call check(.false., 'the same ring length restored')
      end if
      call delete_file('test_domains_on_demand.sav')
   end subroutine test_save_released

   !> The domain lists of A and B are the same: count, rings, areas, sides
   !> and the contacts' domain ids. (Not the 1989 addresses: B's records were
   !> matched, at the synchronisation after the dry CYCLE, to the list built
   !> at that CYCLE's start, A's to the list built after it.)
   subroutine same_domains(a, b, when)
      type(session_t), intent(in) :: a, b
      character(len=*), intent(in) :: when
      integer(ip) :: nd, nr, nc, ndiff
      associate (da => a%model%geometry%domains, db => b%model%geometry%domains, &
                 ca => a%model%geometry%contacts, cb => b%model%geometry%contacts)
         call check_equal(da%n, db%n, when//': same number of domains')
         call check_equal(da%nring, db%nring, when//': same ring length')
         call check_equal(ca%n, cb%n, when//': same number of contacts')
         if (da%n /= db%n .or. da%nring /= db%nring .or. ca%n /= cb%n) return
         nd = da%n
         nr = da%nring
         nc = ca%n
         call check(nd > 0, when//': domains built')
         ndiff = count(da%ring(1:nr) /= db%ring(1:nr)) + count(da%first(1:nd) /= db%first(1:nd)) &
                 + count(da%count(1:nd) /= db%count(1:nd)) + count(da%area(1:nd) /= db%area(1:nd)) &
                 + count(da%outer(1:nd) .neqv. db%outer(1:nd))
         call check_equal(ndiff, 0_ip, when//': same rings, areas and sides')
         ndiff = count(ca%dom1(1:nc) /= cb%dom1(1:nc) .and. ca%live(1:nc)) + &
                 count(ca%dom2(1:nc) /= cb%dom2(1:nc) .and. ca%live(1:nc))
         call check_equal(ndiff, 0_ip, when//': same domains either side of each contact')
      end associate
   end subroutine same_domains

end program test_domains_on_demand
