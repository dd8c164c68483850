!> PRINT (commands_print), JPLOT and LINK through the command interpreter, on
!> a 10 x 10 square split at x = 5 and y = 5 into four blocks with centroids
!> 1 (2.5,7.5), 2 (7.5,7.5), 3 (7.5,2.5), 4 (2.5,2.5) (ids as the cutting
!> engine numbers them; checked below before they are relied on).
program test_print
   use core_kinds, only: wp, ip
   use core_error, only: error_t
   use model_history, only: history_add, history_record, hist_xvel, hist_ydis
   use contact_joint_law, only: state_slip, state_fractured
   use commands_session, only: session_t, session_init, session_execute_line
   use testing_session, only: session_run, lines_contain
   use testing, only: check, check_close, check_equal, check_string, testing_finish
   implicit none

   type(session_t) :: session
   character(len=200), allocatable :: lines(:)

   call test_ranges()
   call test_material()
   call test_contacts()
   call test_joint()
   call test_max_status()
   call test_history()
   call test_file()
   call test_errors()
   call test_jplot()
   call test_link()
   call test_cycle_stages()
   call test_settings()
   call testing_finish()

contains

   !> Run one command line; `lines` receives what it printed.
   subroutine run(text)
      character(len=*), intent(in) :: text
      call session_run(session, text, lines)
   end subroutine run

   subroutine new_model()
      type(error_t), allocatable :: error
      call session_init(session, error)
      call check(.not. allocated(error), 'session starts')
      call run('ROUND 0.01')
      call run('BLOCK 0,0 0,10 10,10 10,0')
      call run('SPLIT 5,-1 5,11')
      call run('SPLIT -1,5 11,5')
   end subroutine new_model

   !> Ids in the first column of the table rows under the header `header`.
   function ids_after(header) result(ids)
      character(len=*), intent(in) :: header
      integer, allocatable :: ids(:)
      integer :: i, id, ios
      logical :: in_table
      allocate (ids(0))
      in_table = .false.
      do i = 1, size(lines)
         if (index(lines(i), header) == 1) then
            in_table = .true.
            cycle
         end if
         if (.not. in_table) cycle
         read (lines(i), *, iostat=ios) id
         if (ios /= 0) exit
         ids = [ids, id]
      end do
   end function ids_after

   logical function same_set(a, b)
      integer, intent(in) :: a(:), b(:)
      integer :: i
      same_set = size(a) == size(b)
      if (.not. same_set) return
      do i = 1, size(a)
         same_set = same_set .and. any(b == a(i))
      end do
   end function same_set

   integer function count_containing(text)
      character(len=*), intent(in) :: text
      integer :: i
      count_containing = 0
      do i = 1, size(lines)
         if (index(lines(i), text) > 0) count_containing = count_containing + 1
      end do
   end function count_containing

   !> SET alone and the end of PRINT STATUS: each setting with the default of
   !> UDEC manual (ICG1.5, 1989), Section 4.5 (ROUND 0.5, EDGE twice the
   !> rounding, FRACTION 0.1 1 1, CSCAN 100, DSCAN 3, UPCON 1, OVTOL half the
   !> rounding, JCONDF 2, CAPRATIO 5, PTOL 0.01, EFF, -SFLOW) or SET's value.
   subroutine test_settings()
      type(error_t), allocatable :: error
      integer :: before
      call session_init(session, error)
      before = session%nerrors
      call run('SET')
      call check(session%nerrors == before, 'SET alone is not an error')
      call check(each_once([character(len=69) :: &
                                'ROUND                   0.5', &
                                'EDGE                    1 (twice the rounding)', &
                                'FRACTION                0.1 1 1 (blocks, zones, fluid)', &
                                'SET CSCAN DSCAN UPCON   100 3 1', &
                                'SET OVTOL               0.25 (half the rounding)', &
                                'SET JMATDF JCONDF       the material of a block beside '// &
                                'the contact, 2', &
                                'SET CAPRATIO PTOL       5 0.01', &
                                'SET EFF SFLOW YWTABLE   EFF -SFLOW', &
                                'SET NMECH NTHER         500 0']), &
                 'SET alone prints the manual defaults')
      call run('ROUND 0.1')
      call run('SET OVTOL 0.02 JCONDF 1 CSCAN 50 PTOL 1e4 SFLOW')
      call run('FRACTION 0.2')
      call run('PRINT STATUS')
      call check(each_once([character(len=48) :: &
                                'EDGE                    0.2 (twice the rounding)', &
                                'FRACTION                0.2 1 1', &
                                'SET CSCAN DSCAN UPCON   50 3 1', &
                                'SET OVTOL               0.02', &
                                'the contact, 1', &
                                'SET CAPRATIO PTOL       5 10000', &
                                'EFF SFLOW']), &
                 'PRINT STATUS ends with the settings as SET and ROUND left them')
   end subroutine test_settings

   !> Each text on exactly one printed line.
   logical function each_once(texts)
      character(len=*), intent(in) :: texts(:)
      integer :: i
      each_once = all([(count_containing(trim(texts(i))) == 1, i=1, size(texts))])
   end function each_once

   subroutine test_ranges()
      character(len=*), parameter :: bh = '   BLOCK   MAT  CONS'
      integer, allocatable :: ids(:), expect(:)
      integer(ip) :: c
      real(wp) :: d
      call new_model()
      ! the numbering this file relies on (centroids listed at the top)
      associate (b => session%model%geometry%blocks)
         call check(b%n == 4 .and. abs(b%xc(1) - 2.5_wp) < 1.0e-9_wp .and. &
                    abs(b%yc(1) - 7.5_wp) < 1.0e-9_wp .and. abs(b%xc(4) - 2.5_wp) < 1.0e-9_wp &
                    .and. abs(b%yc(4) - 2.5_wp) < 1.0e-9_wp .and. abs(b%xc(2) - 7.5_wp) &
                    < 1.0e-9_wp .and. abs(b%yc(2) - 7.5_wp) < 1.0e-9_wp, 'block numbering')
      end associate
      call run('PRINT BLOCK')
      call check(same_set(ids_after(bh), [1, 2, 3, 4]), 'no range: all blocks')
      ! box (inclusive, no centroid on its edges); only centroid (2.5,2.5)
      call run('PRINT 0 5 0 5 BLOCK')
      call check(same_set(ids_after(bh), [4]), 'box range selects block 4')
      call run('PRINT 0,5 0,5 BLOCK')
      call check(same_set(ids_after(bh), [4]), 'box range with commas')
      ! region: the left half
      call run('PRINT REG 0,0 0,10 5,10 5,0 BLOCK')
      call check(same_set(ids_after(bh), [1, 4]), 'REG range selects the left blocks')
      ! annulus around (0,0), r <= 5: only (2.5,2.5) at 3.54; (2.5,7.5) is at 7.9
      call run('PRINT ANN 0 0 0 5 BLOCK')
      call check(same_set(ids_after(bh), [4]), 'ANN range selects block 4')
      ! annulus 6 <= r <= 9 around (0,0): (2.5,7.5) and (7.5,2.5) at 7.9; (7.5,7.5) at 10.6
      call run('PRINT ANN 0 0 6 9 BLOCK')
      call check(same_set(ids_after(bh), [1, 3]), 'ANN ring selects blocks 1 and 3')
      call run('PRINT ANN 0 0 6 9 RIGID')
      call check(same_set(ids_after('   BLOCK          MASS'), [1, 3]), 'ANN range for RIGID')
      call run('PRINT REG 0,0 0,10 5,10 5,0 LIST')
      call check(same_set(ids_after('   BLOCK  CORNERS'), [1, 4]), 'REG range for LIST')
      ! corners in the box 4 < x < 6, -1 < y < 11: the four blocks' corners on x = 5
      ! (two each), reference: the corner list itself
      call run('PRINT 4 6 -1 11 CORNERS')
      allocate (expect(0))
      associate (cr => session%model%geometry%corners)
         do c = 1, cr%n
            if (cr%live(c) .and. abs(cr%x(c) - 5.0_wp) < 1.0_wp) expect = [expect, int(c)]
         end do
      end associate
      ids = ids_after('  CORNER   BLOCK')
      call check_equal(size(ids), 8, 'box range for CORNERS: 8 corners on x = 5')
      call check(same_set(ids, expect), 'box range for CORNERS: the corners on x = 5')
      ! contacts in the annulus around the centre r <= 1: the ones at (5,5)
      call run('PRINT ANN 5 5 0 1 CONTACT STATE')
      deallocate (expect)
      allocate (expect(0))
      associate (ct => session%model%geometry%contacts)
         do c = 1, ct%n
            d = hypot(ct%x(c) - 5.0_wp, ct%y(c) - 5.0_wp)
            if (ct%live(c) .and. d <= 1.0_wp) expect = [expect, int(c)]
         end do
      end associate
      ids = ids_after(' CONTACT  BLOCK1  BLOCK2 TYPE')
      call check(size(ids) > 0 .and. size(ids) < session%model%geometry%contacts%n, &
                 'ANN range for CONTACT keeps some contacts')
      call check(same_set(ids, expect), 'ANN range for CONTACT: the contacts at (5,5)')
      ! domains: the outer domain's centre is the mean of all its boundary contacts
      call run('PRINT 4 6 4 6 DOMAIN')
      call check(size(ids_after('  DOMAIN          AREA')) >= 1, 'box range for DOMAIN')
      call run('PRINT 20 30 20 30 DOMAIN')
      call check_equal(size(ids_after('  DOMAIN          AREA')), 0, 'empty box: no domains')
   end subroutine test_ranges

   subroutine test_material()
      call new_model()
      session%model%geometry%blocks%material(3) = 2
      call run('PRINT MAT 2 BLOCK')
      call check(same_set(ids_after('   BLOCK   MAT  CONS'), [3]), 'MAT 2 selects block 3')
      call run('PRINT ANN 0 0 6 9 MAT 1 BLOCK')
      call check(same_set(ids_after('   BLOCK   MAT  CONS'), [1]), 'range and MAT combine')
      call run('PRINT MAT 2 RIGID')
      call check(same_set(ids_after('   BLOCK          MASS'), [3]), 'MAT for RIGID')
      call run('PRINT MAT 2 STATUS')
      call check(count_containing('Note: PRINT MAT n selects blocks') == 1, &
                 'MAT without BLOCK/RIGID is noted')
   end subroutine test_material

   !> The row of entity `id` in the table under `header` ('' if absent).
   function table_row(header, id) result(row)
      character(len=*), intent(in) :: header
      integer, intent(in) :: id
      character(len=200) :: row
      integer :: i, k, ios
      logical :: in_table
      row = ''
      in_table = .false.
      do i = 1, size(lines)
         if (index(lines(i), header) == 1) then
            in_table = .true.
            cycle
         end if
         if (.not. in_table) cycle
         read (lines(i), *, iostat=ios) k
         if (ios /= 0) return
         if (k == id) then
            row = lines(i)
            return
         end if
      end do
   end function table_row

   !> Fixed layout (docs/print.md): the header line under `header` is as long
   !> as the first row below it, so every header ends over its column.
   subroutine check_aligned(header)
      character(len=*), intent(in) :: header
      integer :: i
      do i = 1, size(lines) - 1
         if (index(lines(i), header) /= 1) cycle
         call check_equal(len_trim(lines(i + 1)), len_trim(lines(i)), &
                          'header and row widths: '//header)
         return
      end do
      call check(.false., 'table missing: '//header)
   end subroutine check_aligned

   subroutine test_contacts()
      character(len=*), parameter :: sh = ' CONTACT  BLOCK1  BLOCK2 TYPE'
      character(len=*), parameter :: fh = ' CONTACT  BLOCK1  BLOCK2        LENGTH'
      character(len=*), parameter :: dh = ' CONTACT  BLOCK1  BLOCK2             X'
      character(len=200) :: row
      integer :: c, b1, b2, ios
      real(wp) :: v(5)
      call new_model()
      call run('PRINT CONTACT')
      call check(count_containing(sh) == 1 .and. count_containing(dh) == 1 .and. &
                 count_containing(fh) == 1, 'PRINT CONTACT alone prints STATE, DISP and FORCE')
      call check(session%model%geometry%contacts%length(2) > 0.0_wp, 'contact 2 has a length')
      associate (st => session%model%geometry%contacts%state)
         st%flags(2) = ior(state_slip, state_fractured)
         st%fn(2) = 5.0_wp
         st%fs(2) = -1.25_wp
         st%us(2) = 0.003_wp
         st%un(2) = -0.001_wp
      end associate
      call run('PRINT CONTACT STATE')
      call check(count_containing(dh) == 0 .and. count_containing(fh) == 0, &
                 'STATE only: no DISP or FORCE table')
      row = table_row(sh, 2)
      ! the flags, then the 1989 address (i9)
      call check_string(row(len_trim(row) - 11:len_trim(row) - 9), 'S-F', &
                        'state flags slip and fractured of contact 2')
      call run('PRINT CONTACT')
      call check_aligned(sh)
      call check_aligned(dh)
      call check_aligned(fh)
      call run('PRINT BLOCK RIGID CORNERS')
      call check_aligned('   BLOCK   MAT  CONS')
      call check_aligned('   BLOCK          MASS')
      call check_aligned('  CORNER   BLOCK')
      call run('PRINT JOINT 5,-1 5,11 0.1')
      call check_aligned(' CONTACT  BLOCK1  BLOCK2         ALONG')
      call run('PRINT MAX')
      call check_equal(len_trim(lines(1)), len_trim(lines(6)), &
                       'MAX header as wide as a value line with an id')
      call run('PRINT CONTACT FORCE DISP')
      call check(index(lines(1), fh) == 1 .and. count_containing(dh) == 1 .and. &
                 count_containing(sh) == 0, 'FORCE then DISP, in the order given')
      ! FORCE row: length, fn, fs, then fn/length and fs/length (6 digits printed)
      row = table_row(fh, 2)
      read (row, *, iostat=ios) c, b1, b2, v
      call check(ios == 0, 'FORCE row of contact 2 read')
      associate (len => session%model%geometry%contacts%length(2))
         call check_close(v(1), len, 1.0e-5_wp, 'FORCE: length')
         call check_close(v(2), 5.0_wp, 1.0e-5_wp, 'FORCE: fn')
         call check_close(v(3), -1.25_wp, 1.0e-5_wp, 'FORCE: fs')
         call check_close(v(4), 5.0_wp/len, 1.0e-5_wp, 'FORCE: normal stress')
         call check_close(v(5), -1.25_wp/len, 1.0e-5_wp, 'FORCE: shear stress')
      end associate
      ! DISP row: x, y, us, un, gap
      row = table_row(dh, 2)
      read (row, *, iostat=ios) c, b1, b2, v
      call check(ios == 0, 'DISP row of contact 2 read')
      call check_close(v(3), 0.003_wp, 1.0e-5_wp, 'DISP: us')
      call check_close(v(4), -0.001_wp, 1.0e-5_wp, 'DISP: un')
   end subroutine test_contacts

   subroutine test_joint()
      integer, allocatable :: ids(:), expect(:), on_joint(:)
      integer(ip) :: c
      integer :: i, ios, id, b1, b2
      real(wp) :: along, last
      logical :: sorted
      call new_model()
      call run('PRINT JOINT 5,-1 5,11 0.1')
      ! reference: contacts whose point is within 0.1 of the line x = 5, -1 <= y <= 11
      allocate (expect(0))
      associate (ct => session%model%geometry%contacts)
         do c = 1, ct%n
            if (ct%live(c) .and. abs(ct%x(c) - 5.0_wp) <= 0.1_wp) expect = [expect, int(c)]
         end do
      end associate
      ids = ids_after(' CONTACT  BLOCK1  BLOCK2         ALONG')
      call check(size(ids) > 0 .and. same_set(ids, expect), 'JOINT selects contacts on x = 5')
      on_joint = expect
      sorted = .true.
      last = -1.0_wp
      do i = 3, size(lines)
         read (lines(i), *, iostat=ios) id, b1, b2, along
         if (ios /= 0) cycle
         sorted = sorted .and. along >= last
         last = along
      end do
      call check(sorted, 'JOINT rows ordered along the line')
      ! the right half of y = 5 only: the contact at (10,5) and none at x = 5
      call run('PRINT JOINT 6,5 11,5 0.1')
      deallocate (expect)
      allocate (expect(0))
      associate (ct => session%model%geometry%contacts)
         do c = 1, ct%n
            if (ct%live(c) .and. abs(ct%y(c) - 5.0_wp) <= 0.1_wp .and. ct%x(c) >= 5.9_wp) &
               expect = [expect, int(c)]
         end do
      end associate
      ids = ids_after(' CONTACT  BLOCK1  BLOCK2         ALONG')
      call check(size(ids) >= 1 .and. same_set(ids, expect), 'JOINT on a short line')
      ! default band: +/- the rounding length (0.01); a line 0.05 off x = 5 finds nothing
      call run('PRINT JOINT 5.05,-1 5.05,11')
      call check_equal(size(ids_after(' CONTACT  BLOCK1  BLOCK2         ALONG')), 0, &
                       'default band is the rounding length')
      call run('PRINT JOINT 5.05,-1 5.05,11 0.06')
      call check(same_set(ids_after(' CONTACT  BLOCK1  BLOCK2         ALONG'), on_joint), &
                 'a band of 0.06 reaches the contacts on x = 5')
   end subroutine test_joint

   subroutine test_max_status()
      call new_model()
      associate (b => session%model%geometry%blocks)
         b%mass(1:4) = [4.0_wp, 1.0_wp, 2.0_wp, 3.0_wp]
         b%vx(3) = 3.0_wp
         b%vy(3) = 4.0_wp
         b%ux(2) = -0.5_wp
         b%fy(4) = 7.0_wp
      end associate
      call run('PRINT MAX')
      call check(count_containing('number of blocks                         4') == 1, &
                 'MAX counts 4 blocks')
      ! |v| = hypot(3, 4) = 5 at block 3; mass min 1 (block 2), max 4 (block 1), mean 2.5
      call max_value('max block velocity', 5.0_wp, 3, 'largest velocity')
      call max_value('block mass, minimum', 1.0_wp, 2, 'smallest mass')
      call max_value('block mass, maximum', 4.0_wp, 1, 'largest mass')
      call max_value('block mass, average', 2.5_wp, 0, 'mean mass')
      call max_value('max block displacement', 0.5_wp, 2, 'largest displacement')
      call max_value('max unbalanced force', 7.0_wp, 4, 'largest unbalanced force')
      session%model%geometry%contacts%state%fn(3) = 9.0_wp
      session%model%geometry%contacts%state%us(5) = -0.25_wp
      call run('PRINT MAX')
      call max_value('max normal force', 9.0_wp, 3, 'largest fn')
      call max_value('max |shear displacement|', 0.25_wp, 5, 'largest |us|')
      ! range: only block 4 (centroid 2.5,2.5)
      call run('PRINT 0 5 0 5 MAX')
      call check(count_containing('number of blocks                         1') == 1, &
                 'MAX with a range counts the blocks inside')
      call max_value('max unbalanced force', 7.0_wp, 4, 'range keeps block 4')
      call run('PRINT STATUS')
      call check(count_containing('  blocks                  4') == 1, 'STATUS blocks')
      call check(count_containing('  cycles                  0') == 1, 'STATUS cycles')
      call check(count_containing('  damping                 none') == 1, 'STATUS damping')
      call run('GRAVITY 0 -9.81')
      call run('PRINT STATUS')
      call check(count_containing('  gravity (x, y)          0 -9.81') == 1, 'STATUS gravity')
   end subroutine test_max_status

   !> Check the PRINT MAX line `label`: value (and entity id when entity > 0).
      subroutine max_value(label, expect, entity, what)
         character(len=*), intent(in) :: label, what
         real(wp), intent(in) :: expect
         integer, intent(in) :: entity
         integer :: k, ios, got
         real(wp) :: value
         character(len=8) :: kind
         do k = 1, size(lines)
            if (index(lines(k), '  '//label) /= 1) cycle
            if (entity > 0) then
               read (lines(k)(31:), *, iostat=ios) value, kind, got
               call check(ios == 0 .and. got == entity, 'MAX '//what//': id')
            else
               read (lines(k)(31:), *, iostat=ios) value
            end if
            ! printed with 6 significant digits
            call check_close(value, expect, 1.0e-5_wp, 'MAX '//what)
            return
         end do
         call check(.false., 'MAX line missing: '//label)
      end subroutine max_value

   subroutine test_history()
      real(wp) :: t, a, b
      integer :: ios, nrow, i
      type(error_t), allocatable :: error
      call session_init(session, error)
      call run('PRINT HIST')
      call check(count_containing('no histories defined') == 1, 'HIST: none defined')
      call history_add(session%model%hist, hist_xvel, 7_ip, 1.0_wp, 2.0_wp, 1.0_wp, 2.0_wp)
      call history_add(session%model%hist, hist_ydis, 9_ip, 3.0_wp, 4.0_wp, 3.0_wp, 4.5_wp)
      do i = 1, 3
         call history_record(session%model%hist, 0.1_wp*i, int(10*i, ip), &
                             [real(i, wp), -2.0_wp*i*i])
      end do
      call run('PRINT HIST')
      call check(count_containing(' XVEL ') == 1 .and. count_containing(' YDIS ') == 1, &
                 'HIST lists the variables')
      call check_aligned('    HIST  TYPE     ENTITY')
      call run('PRINT HIST 1 2')
      call check(index(lines(1), 'TIME') > 0 .and. index(lines(1), '1 XVEL') > 0 .and. &
                 index(lines(1), '2 YDIS') > 0, 'HIST header: time, then one column each')
      nrow = 0
      do i = 2, size(lines)
         read (lines(i), *, iostat=ios) t, a, b
         if (ios /= 0) cycle
         nrow = nrow + 1
         ! samples recorded above: t = 0.1 i, xvel = i, ydis = -2 i^2 (6 digits printed)
         call check_close(t, 0.1_wp*nrow, 1.0e-5_wp, 'HIST time column')
         call check_close(a, real(nrow, wp), 1.0e-5_wp, 'HIST column 1')
         call check_close(b, -2.0_wp*nrow*nrow, 1.0e-5_wp, 'HIST column 2')
      end do
      call check_equal(nrow, 3, 'HIST prints every sample')
      call run('PRINT HIST 2')
      read (lines(2), *, iostat=ios) t, a
      call check(ios == 0 .and. abs(a + 2.0_wp) < 1.0e-5_wp .and. len_trim(lines(2)) == 28, &
                 'HIST 2: time and one column (28 characters)')
      call run('PRINT HIST 5 1')
      call check(count_containing('history 5 is not defined') == 1, 'undefined history noted')
      call check(session%nerrors == 0, 'undefined history is not an input error')
      call run('PRINT HMAX 2')
      ! ydis = -2, -8, -18: maximum -2 at t = 0.1, minimum -18 at t = 0.3
      block
         integer :: id
         character(len=5) :: name
         real(wp) :: vmax, tmax, vmin, tmin
         read (lines(2), *, iostat=ios) id, name, vmax, tmax, vmin, tmin
         call check(ios == 0 .and. id == 2 .and. name == 'YDIS', 'HMAX row')
         call check_close(vmax, -2.0_wp, 1.0e-5_wp, 'HMAX maximum')
         call check_close(tmax, 0.1_wp, 1.0e-5_wp, 'HMAX time of maximum')
         call check_close(vmin, -18.0_wp, 1.0e-5_wp, 'HMAX minimum')
         call check_close(tmin, 0.3_wp, 1.0e-5_wp, 'HMAX time of minimum')
      end block
      call run('PRINT HMAX')
      call check_equal(size(lines), 3, 'HMAX without ids: every history')
      call check_aligned('    HIST  TYPE        MAXIMUM')
      call run('PRINT HIST 1 2')
      call check_aligned('          TIME')
   end subroutine test_history

   subroutine test_file()
      character(len=*), parameter :: name = 'test_print_file.txt'
      integer :: u, ios, n
      logical :: exists
      character(len=200) :: line
      call new_model()
      call run('PRINT FILE '//name//' BLOCK')
      call check_equal(size(lines), 0, 'PRINT FILE: nothing on the screen')
      inquire (file=name, exist=exists)
      call check(exists, 'PRINT FILE writes the file')
      inquire (file=name//'.udec-tmp', exist=exists)
      call check(.not. exists, 'PRINT FILE leaves no temporary')
      open (newunit=u, file=name, status='old', action='read')
      n = 0
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         n = n + 1
         if (n == 1) call check(index(line, '   BLOCK   MAT  CONS') == 1, 'file holds the table')
      end do
      close (u)
      call check_equal(n, 5, 'file: header and 4 blocks')
      ! keywords before FILE go to the screen; the file is replaced, not appended
      call run('PRINT STATUS FILE '//name//' CORNERS')
      call check(count_containing('  blocks ') == 1 .and. count_containing('CORNER') == 0, &
                 'STATUS on the screen, CORNERS in the file')
      open (newunit=u, file=name, status='old', action='read')
      n = 0
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         n = n + 1
      end do
      close (u, status='delete')
      call check_equal(n, 17, 'file replaced: corner header and 16 corners')
      call run('PRINT FILE no-such-dir-udec/x.txt BLOCK')
      call check(count_containing("PRINT FILE: cannot open 'no-such-dir-udec/x.txt'") == 1, &
                 'unwritable FILE is an error')
   end subroutine test_file

   subroutine test_errors()
      integer :: before
      type(error_t), allocatable :: error
      call session_init(session, error)
      ! an empty model prints as empty (as ZONE, HIST, BOUNDARY): no error, so
      ! a batch deck goes on, and the other keywords of the line still print
      before = session%nerrors
      call run('PRINT BLOCK CONTACT CORNERS DOMAINS JOINT 0 0 1 1 PROP')
      call check(session%nerrors == before, 'PRINT before BLOCK is not an error')
      call check(each_once([character(len=48) :: &
                                'PRINT BLOCKS: none (no BLOCK has been created)', &
                                'PRINT CONTACTS: none (no BLOCK has been created)', &
                                'PRINT CORNERS: none', &
                                'PRINT DOMAINS: none', &
                                'PRINT JOINT: none', &
                                '(no properties given)']), &
                 'PRINT before BLOCK: each keyword says the model is empty, PROP still prints')
      call run('PRINT MAX')
      call check(count_containing('number of blocks                         0') == 1, &
                 'PRINT MAX works on an empty model')
      call new_model()
      before = session%nerrors
      call run('PRINT BLOCK DISP')
      call check(session%nerrors == before + 1 .and. size(lines) == 1 .and. &
                 index(lines(1), 'PRINT DISPLACEMENTS: give it after CONTACT') > 0, &
                 'misplaced sub-keyword: an error and nothing printed')
      call run('PRINT 0 5 0 5')
      call check(count_containing('PRINT: expected a keyword') == 1, 'PRINT needs a keyword')
      call run('PRINT JOINT')
      call check(count_containing('PRINT JOINT: expected x1 y1 x2 y2') == 1, &
                 'JOINT without its line is an error')
      before = session%nerrors
      call run('PRINT ZONE STATE GRID FLOW STE MAX')
      call check(session%nerrors == before, 'unavailable data is not an input error')
      call check(count_containing('not yet available') == 1, 'one not-yet-available line (FLOW)')
      call check(count_containing('there are no structural elements') == 1, &
                 'STE without structures says so')
      call check(count_containing('no zones: FDEF blocks have not been zoned') == 2, &
                 'ZONE and GRIDPOINT before GENERATE: a note each')
      call check(count_containing('number of blocks') == 1, 'the run of keywords goes on')
      call run('PRINT BOUND')
      call check(count_containing('no boundary conditions') == 1, 'PRINT BOUND')
      call run('PRINT PROP')
      call check(count_containing('(no properties given)') == 1, 'PRINT PROP, none given')
      call run('PROP MAT=1 DENS=2000 JKN=1e9 KN=3')
      call run('PRINT PROP JOINT')
      call check(count_containing('JKN') == 1 .and. count_containing('DENSITY') == 0 .and. &
                 count_containing(' KN ') == 0, 'PRINT PROP JOINT: joint properties only')
      call run('PRINT PROP BLOCK CONTACT')
      call check(count_containing('DENSITY') == 1 .and. count_containing(' KN ') == 1 .and. &
                 count_containing('JKN') == 0, 'PRINT PROP BLOCK CONTACT: two kinds')
   end subroutine test_errors

   subroutine test_jplot()
      integer(ip) :: nblocks, i
      logical :: ok
      call new_model()
      call run('DELETE BLOCK 3')
      call run('DELETE BLOCK 4')
      ! two blocks left: 1 (0..5 x 5..10) and 2 (5..10 x 5..10)
      nblocks = count(session%model%geometry%blocks%live(1:session%model%geometry%blocks%n))
      call run('JPLOT START')
      call check(session%model%geometry%jplot%on, 'JPLOT START turns recording on')
      call run('CRACK -1,7 11,7')
      call check_equal(count(session%model%geometry%blocks%live(1: &
                       session%model%geometry%blocks%n)), nblocks, 'CRACK under JPLOT: no split')
      call check_equal(session%model%geometry%jplot%n, 2, 'CRACK recorded as two pieces')
      ok = .true.
      associate (j => session%model%geometry%jplot)
         do i = 1, j%n
            ! the pieces lie on y = 7 inside the blocks, ends at x = 0, 5, 10
            ok = ok .and. abs(j%y1(i) - 7.0_wp) < 1.0e-9_wp .and. &
                 abs(j%y2(i) - 7.0_wp) < 1.0e-9_wp
            ok = ok .and. any(abs(min(j%x1(i), j%x2(i)) - [0.0_wp, 5.0_wp]) < 1.0e-9_wp)
            ok = ok .and. any(abs(max(j%x1(i), j%x2(i)) - [5.0_wp, 10.0_wp]) < 1.0e-9_wp)
            ok = ok .and. (j%block(i) == 1 .or. j%block(i) == 2)
         end do
         call check(ok .and. j%block(1) /= j%block(2), 'JPLOT pieces: coordinates and blocks')
      end associate
      call run('CRACK 1,8 2,8')
      call check_equal(session%model%geometry%pending%n, 0, &
                       'a partial crack under JPLOT is not kept as pending')
      call check_equal(session%model%geometry%jplot%n, 3, 'the partial crack is recorded')
      call run('JSET 90,0 100,0 0,0 2,0')
      call check(session%model%geometry%jplot%n > 3, 'JSET recorded')
      call check_equal(count(session%model%geometry%blocks%live(1: &
                       session%model%geometry%blocks%n)), nblocks, 'JSET under JPLOT: no split')
      call run('SPLIT -1,9 11,9')
      call check(count_containing('JPLOT records only CRACK and JSET') == 1, &
                 'SPLIT under JPLOT is noted')
      call check(count(session%model%geometry%blocks%live(1: &
                 session%model%geometry%blocks%n)) == nblocks + 2, 'SPLIT still cuts')
      nblocks = nblocks + 2
      call run('JPLOT STOP')
      call check(.not. session%model%geometry%jplot%on .and. &
                 session%model%geometry%jplot%n > 3, 'JPLOT STOP keeps the list')
      call run('CRACK -1,6 11,6')
      call check_equal(count(session%model%geometry%blocks%live(1: &
                       session%model%geometry%blocks%n)), nblocks + 2, 'after STOP, CRACK cuts')
      call run('JPLOT START')
      call check_equal(session%model%geometry%jplot%n, 0, 'JPLOT START clears the list')
      call run('JPLOT')
      call check(count_containing('JPLOT: expected exactly one of START or STOP') == 1, &
                 'JPLOT needs START or STOP')
   end subroutine test_jplot

   subroutine test_link()
      integer :: before
      call new_model()
      before = session%nerrors
      call run('LINK 2,8 8,8')
      call check(session%nerrors == before .and. &
                 count_containing('LINK: blocks 1 and 2 need no link') == 1, 'LINK accepted')
      call run('LINK 20,20 8,8')
      call check(count_containing('LINK: the first point (20, 20) is not inside any block') &
                 == 1, 'LINK: first point outside')
      call run('LINK 2,8 8,-3')
      call check(count_containing('LINK: the second point (8, -3) is not inside any block') &
                 == 1, 'LINK: second point outside')
      call run('LINK 2,8 3,9')
      call check(count_containing('both points lie inside block 1') == 1, 'LINK: same block')
      call run('LINK 5,8 8,8')
      call check(count_containing('lies on the boundary of block') == 1, &
                 'LINK: point on a joint')
      call check(session%nerrors == before + 4, 'four LINK errors')
   end subroutine test_link

   !> PRINT CYCLE: the stages this model runs (only those its physics asks
   !> for) and, after a CYCLE, each stage's share of the wall time.
   subroutine test_cycle_stages()
      call new_model()
      call run('PROP MAT=1 DENS=2000 JKN=1e9 JKS=1e9 JFRIC=30')
      call run('PRINT CYCLE')
      call check(lines_contain(lines, 'block motion'), 'PRINT CYCLE: rigid blocks move')
      call check(lines_contain(lines, 'contact forces'), 'PRINT CYCLE: contacts load blocks')
      call check(.not. lines_contain(lines, 'zone stresses'), &
                 'PRINT CYCLE: a rigid-block model runs no zone stage')
      call check(.not. lines_contain(lines, 'fluid'), 'PRINT CYCLE: no fluid stage without FLUID')
      call check(.not. lines_contain(lines, 'adaptive damping'), 'PRINT CYCLE: no damping stage')
      call check(.not. lines_contain(lines, 'histories'), 'PRINT CYCLE: no history stage')
      call check(lines_contain(lines, 'No CYCLE has run yet'), 'PRINT CYCLE: no timing before CYCLE')
      call run('PRINT CY')
      call check(lines_contain(lines, 'block motion'), 'PRINT CY abbreviates CYCLE')
      call run('DAMP AUTO')
      call run('HIST UNBAL')
      call run('PRINT CYCLE')
      call check(lines_contain(lines, 'adaptive damping'), 'PRINT CYCLE: DAMP AUTO adds its stage')
      call check(lines_contain(lines, 'histories'), 'PRINT CYCLE: HISTORY adds its stage')
      call run('CYCLE 5')
      call run('PRINT CYCLE')
      call check(lines_contain(lines, 'Last CYCLE: 5 steps'), 'PRINT CYCLE: steps of the last CYCLE')
      call check(lines_contain(lines, 'set-up'), 'PRINT CYCLE: set-up time after a CYCLE')
      call check(lines_contain(lines, ' %'), 'PRINT CYCLE: shares of the wall time')
      call run('DAMP 0 0')
      call run('CYCLE 1')
      call run('PRINT CYCLE')
      call check(.not. lines_contain(lines, 'adaptive damping'), &
                 'PRINT CYCLE: the damping stage goes when DAMP AUTO is switched off')
      call run('NEW')
      call run('PRINT CYCLE')
      call check(lines_contain(lines, 'No CYCLE has run yet'), &
                 'PRINT CYCLE: NEW forgets the timing of the old model')
   end subroutine test_cycle_stages

end program test_print
