!> Contact detection, domains and PRINT output on known geometries.
program test_geometry_contacts
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use core_output, only: output_t
   use core_range, only: range_t, range_box
   use model_geometry, only: geometry_t, geometry_init
   use geometry_cutting, only: cut_create_block, cut_split, cut_set_round, cut_delete_block
   use contact_detection, only: contact_rebuild
   use contact_domains, only: domain_rebuild
   use contact_refresh, only: geometry_refresh
   use contact_checks, only: check_blocks, check_contacts, check_domains
   use contact_print, only: print_block_table, print_corners, print_contact_table, print_domains, &
                            print_list
   use testing, only: check, check_close, check_equal, check_string, testing_finish
   implicit none

   call test_two_blocks()
   call test_grid()
   call test_tutorial()
   call test_prints()
   call testing_finish()

contains

   subroutine all_checks(geo, label)
      type(geometry_t), intent(in) :: geo
      character(len=*), intent(in) :: label
      type(error_t), allocatable :: error
      call check_blocks(geo, 1.0e-9_wp, error)
      if (allocated(error)) print '(a)', error%message
      call check(.not. allocated(error), label//': blocks')
      call check_contacts(geo, error)
      if (allocated(error)) print '(a)', error%message
      call check(.not. allocated(error), label//': contacts')
      call check_domains(geo, error)
      if (allocated(error)) print '(a)', error%message
      call check(.not. allocated(error), label//': domains')
   end subroutine all_checks

   subroutine square(geo, s)
      type(geometry_t), intent(inout) :: geo
      real(wp), intent(in) :: s
      type(error_t), allocatable :: error
      call geometry_init(geo)
      call cut_set_round(geo, 0.01_wp, error)
      call cut_create_block(geo, [0.0_wp, 0.0_wp, s, s], [0.0_wp, s, s, 0.0_wp], 1, 1, error)
   end subroutine square

   subroutine test_two_blocks()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      integer(ip) :: c
      call square(geo, 10.0_wp)
      call cut_split(geo, 4.0_wp, -1.0_wp, 4.0_wp, 11.0_wp, error)
      call check(.not. geo%contacts_valid, 'contacts stale after a split')
      call geometry_refresh(geo)
      call check(geo%contacts_valid .and. geo%domains_valid, 'refresh rebuilds')
      call check_equal(geo%contacts%n, 2, 'two blocks: 2 contacts')
      do c = 1, geo%contacts%n
         call check_equal(int(geo%contacts%kind(c)), 1, 'two blocks: corner-corner at joint ends')
         call check_close(geo%contacts%length(c), 5.0_wp, 1.0e-12_wp, 'half the joint each')
         call check_close(abs(geo%contacts%nx(c)), 1.0_wp, 1.0e-9_wp, 'normal across joint')
         call check_equal(int(geo%contacts%jcons(c)), 2, 'default JCONS')
         call check_equal(geo%contacts%jmat(c), 1, 'joint material from block')
      end do
      ! normal points from block1 to block2
      c = 1
      call check((geo%blocks%xc(geo%contacts%block2(c)) - geo%blocks%xc(geo%contacts%block1(c))) &
                 *geo%contacts%nx(c) > 0.0_wp, 'normal from block1 to block2')
      call check_equal(geo%domains%n, 2, 'two blocks: joint void and outer domain')
      call check_close(geo%domains%area(geo%outer_domain), -100.0_wp, 1.0e-12_wp, &
                       'outer domain area')
      call all_checks(geo, 'two blocks')
   end subroutine test_two_blocks

   !> Verification test D geometry: 5 x 5 blocks.
   subroutine test_grid()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      integer(ip) :: i, ncc
      call square(geo, 10.0_wp)
      do i = 1, 4
         call cut_split(geo, -1.0_wp, 2.0_wp*i, 12.0_wp, 2.0_wp*i, error)
         call cut_split(geo, 2.0_wp*i, 11.0_wp, 2.0_wp*i, -1.0_wp, error)
      end do
      call contact_rebuild(geo)
      call domain_rebuild(geo)
      ! 40 edge-sharing pairs x 2 + 32 diagonal corner touches
      call check_equal(geo%contacts%n, 112, 'grid: contacts')
      ncc = count(geo%contacts%kind(1:geo%contacts%n) == 1)
      call check_equal(ncc, 112, 'grid: all corner-corner')
      ! Euler: domains = contacts - blocks + 2 - 2*genus; each of the 16 four-block
      ! junctions carries two crossing diagonal contacts, which adds one to the genus
      call check_equal(geo%domains%n, 112 - 25 + 2 - 2*16, 'grid: domains')
      call check_equal(count(geo%domains%outer(1:geo%domains%n)), 1, 'grid: one outer')
      call all_checks(geo, 'grid')
      ! delete the middle block: its void becomes one domain of area 4
      call cut_delete_block(geo, 13, error)
      call contact_rebuild(geo)
      call domain_rebuild(geo)
      call all_checks(geo, 'grid with hole')
      call check_close(maxval(geo%domains%area(1:geo%domains%n)), 4.0_wp, 1.0e-9_wp, &
                       'hole domain area')
   end subroutine test_grid

   subroutine test_tutorial()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      integer(ip) :: c, n2
      call square(geo, 20.0_wp)
      call cut_split(geo, 0.0_wp, 2.0_wp, 20.0_wp, 8.0_wp, error)
      call cut_split(geo, 5.0_wp, 3.0_wp, 5.0_wp, 20.0_wp, error)
      call cut_split(geo, 5.0_wp, 12.0_wp, 20.0_wp, 18.0_wp, error)
      call contact_rebuild(geo)
      call domain_rebuild(geo)
      call all_checks(geo, 'tutorial')
      ! T-junction at (5,12): corner-edge contact with the upper-left block
      n2 = 0
      do c = 1, geo%contacts%n
         if (geo%contacts%kind(c) /= 1 .and. abs(geo%contacts%x(c) - 5.0_wp) < 1.0e-9_wp .and. &
             abs(geo%contacts%y(c) - 12.0_wp) < 1.0e-9_wp) n2 = n2 + 1
      end do
      call check_equal(n2, 2, 'tutorial: two corner-edge contacts at the T-junction')
   end subroutine test_tutorial

   subroutine test_prints()
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      type(output_t) :: out
      type(range_t) :: box
      integer :: u, ios, nlines
      character(len=200) :: line, first
      call square(geo, 10.0_wp)
      call cut_split(geo, 5.0_wp, -1.0_wp, 5.0_wp, 11.0_wp, error)
      call contact_rebuild(geo)
      call domain_rebuild(geo)
      open (newunit=u, status='scratch', action='readwrite')
      out%screen = .false.
      call out%add_unit(u)
      call print_block_table(geo, out, 'BLOCKS')
      call print_corners(geo, out)
      call print_contact_table(geo, out, 'STATE')
      call print_domains(geo, out)
      call print_list(geo, out)
      box = range_t(kind=range_box, xl=0.0_wp, xu=4.0_wp, yl=0.0_wp, yu=10.0_wp)
      call print_block_table(geo, out, 'BLOCKS', box)
      rewind (u)
      nlines = 0
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         nlines = nlines + 1
         if (nlines == 2) first = line
      end do
      close (u)
      ! 3 block lines, 9 corner lines, 3 contact, 3 domain, 3 list, 2 ranged
      call check_equal(nlines, 3 + 9 + 3 + 3 + 3 + 2, 'print line count')
      call check_string(first(1:30), '       1     1     1     4     ', 'print block row')
   end subroutine test_prints

end program test_geometry_contacts
