!> A small stroke (vector) font of our own for the raster device, which has
!> no fonts: every printable ASCII character is a few pen strokes on a grid.
!>
!> Glyph grid: x from 0 (left) to at most 4, y from 0 (descender) through 2
!> (baseline) and 6 (x-height) to 8 (cap height); brackets reach 1 and 9.
!> A glyph is a string of strokes separated by blanks; a stroke is a list of
!> points, two digits each (x then y). The advance of a glyph is its widest x
!> plus 2 (a blank advances 4). The text size asked for is the cap height, so
!> one grid unit is size/6.
module plot_font
   use core_constants, only: pi
   use core_kinds, only: wp
   implicit none
   private
   public :: font_glyph, font_text_width, font_strokes, font_unit

   !> Grid units per cap height.
   real(wp), parameter :: font_unit = 1.0_wp/6.0_wp

   !> The characters with a glyph, and their strokes in the same order.
   character(len=*), parameter :: glyph_chars = &
      'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz' // &
      '0123456789.,:;-+=()[]/\|*%_!?''"`#<>^~$&@{}'
   character(len=*), parameter :: glyph_strokes(*) = [character(len=35) :: &
      '0206284642 0545', &  ! A
      '02083847463505 3544433202', &  ! B
      '4738180703123243', &  ! C
      '02083847433202', &  ! D
      '48080242 0535', &  ! E
      '480802 0535', &  ! F
      '47381807031232434525', &  ! G
      '0208 4248 0545', &  ! H
      '1232 2228 1838', &  ! I
      '4843321203', &  ! J
      '0208 4804 1542', &  ! K
      '080242', &  ! L
      '0208254842', &  ! M
      '02084248', &  ! N
      '120307183847433212', &  ! O
      '02083847463505', &  ! P
      '120307183847433212 2442', &  ! Q
      '02083847463505 2542', &  ! R
      '473818070615354443321203', &  ! S
      '0848 2822', &  ! T
      '080312324348', &  ! U
      '082248', &  ! V
      '0812253248', &  ! W
      '0842 0248', &  ! X
      '082548 2522', &  ! Y
      '08480242', &  ! Z
      '16364542 441403123243', &  ! a
      '08023243453606', &  ! b
      '461605031242', &  ! c
      '48421203051646', &  ! d
      '044445361605031242', &  ! e
      '48382722 1636', &  ! f
      '43321203051646413000', &  ! g
      '0802 0516364542', &  ! h
      '0602 0807', &  ! i
      '161100 1817', &  ! j
      '0802 3603 1432', &  ! k
      '080312', &  ! l
      '0206 05162522 25364542', &  ! m
      '0206 0516364542', &  ! n
      '120305163645433212', &  ! o
      '00063645433202', &  ! p
      '40461605031242', &  ! q
      '0206 042646', &  ! r
      '4616051434433202', &  ! s
      '18132232 0636', &  ! t
      '0603123243 4642', &  ! u
      '062246', &  ! v
      '0612243246', &  ! w
      '0642 0246', &  ! x
      '0622 461000', &  ! y
      '06460242', &  ! z
      '120307183847433212 1337', &  ! 0
      '172822 1232', &  ! 1
      '07183847460242', &  ! 2
      '07183847463515 354443321203', &  ! 3
      '32380444', &  ! 4
      '4808053544433202', &  ! 5
      '4738180703123243443505', &  ! 6
      '084812', &  ! 7
      '15060718384746351504031232434435', &  ! 8
      '0312324347381807061545', &  ! 9
      '0212', &  ! .
      '131201', &  ! ,
      '0212 0616', &  ! :
      '1616 131201', &  ! ;
      '0535', &  ! -
      '0545 2327', &  ! +
      '0444 0646', &  ! =
      '29070321', &  ! (
      '09272301', &  ! )
      '29090121', &  ! [
      '09292101', &  ! ]
      '0248', &  ! /
      '0842', &  ! \
      '0109', &  ! |
      '2327 0446 0644', &  ! *
      '0248 0818170708 3343423233', &  ! %
      '0141', &  ! _
      '0804 0212', &  ! !
      '07183847462524 2322', &  ! ?
      '0806', &  ! '
      '0806 2826', &  ! "
      '0817', &  ! `
      '1218 3238 0444 0646', &  ! #
      '460442', &  ! <
      '064402', &  ! >
      '062846', &  ! ^
      '05163545', &  ! ~
      '473818070615354443321203 2129', &  ! $
      '42061718372604031222 3443', &  ! &
      '3424133536 364443321203071838474604', &  ! @
      '2938363505343321 0515', &  ! {
      '0918161525141301 2535']  ! }
   !> Strokes of a character the table lacks (those of '?').
   character(len=*), parameter :: missing_glyph = '07183847462524 2322'

contains

   !> Strokes of character `ch` ('?' for characters the table lacks).
   pure function font_glyph(ch) result(g)
      character, intent(in) :: ch
      character(len=:), allocatable :: g
      integer :: k
      k = index(glyph_chars, ch)
      if (k == 0) then
         g = missing_glyph
      else
         g = trim(glyph_strokes(k))
      end if
   end function font_glyph

   !> Advance of one character in grid units.
   pure real(wp) function glyph_advance(ch) result(a)
      character, intent(in) :: ch
      character(len=:), allocatable :: g
      integer :: k, xmax
      if (ch == ' ') then
         a = 4.0_wp
         return
      end if
      g = font_glyph(ch)
      xmax = 0
      k = 1
      do while (k <= len(g))
         if (g(k:k) == ' ') then
            k = k + 1
            cycle
         end if
         xmax = max(xmax, ichar(g(k:k)) - ichar('0'))
         k = k + 2
      end do
      a = real(xmax + 2, wp)
   end function glyph_advance

   !> Width of `text` at cap height `size` (the last character's spacing
   !> is not counted).
   pure real(wp) function font_text_width(text, size) result(w)
      character(len=*), intent(in) :: text
      real(wp), intent(in) :: size
      integer :: i
      w = 0.0_wp
      do i = 1, len(text)
         w = w + glyph_advance(text(i:i))
      end do
      if (len(text) > 0) w = w - 2.0_wp
      w = max(w, 0.0_wp)*size*font_unit
   end function font_text_width

   !> The strokes of `text` with its baseline starting at (x0, y0), rotated
   !> by `angle` degrees about that point. Stroke k is the points
   !> first(k) .. first(k+1)-1 of (x, y).
   pure subroutine font_strokes(text, x0, y0, size, angle, x, y, first, nstroke)
      character(len=*), intent(in) :: text
      real(wp), intent(in) :: x0, y0, size, angle
      real(wp), allocatable, intent(out) :: x(:), y(:)
      integer, allocatable, intent(out) :: first(:)
      integer, intent(out) :: nstroke
      character(len=:), allocatable :: g
      real(wp) :: pen, u, c, s, gx, gy
      integer :: i, k, npt, cap
      u = size*font_unit
      c = cos(angle*pi/180.0_wp)
      s = sin(angle*pi/180.0_wp)
      cap = 0
      do i = 1, len(text)
         cap = cap + len(font_glyph(text(i:i)))
      end do
      allocate (x(cap), y(cap), first(cap + 1))
      npt = 0
      nstroke = 0
      pen = 0.0_wp
      do i = 1, len(text)
         if (text(i:i) /= ' ') then
            g = font_glyph(text(i:i))
            k = 1
            nstroke = nstroke + 1
            first(nstroke) = npt + 1
            do while (k <= len(g))
               if (g(k:k) == ' ') then
                  nstroke = nstroke + 1
                  first(nstroke) = npt + 1
                  k = k + 1
                  cycle
               end if
               gx = pen + real(ichar(g(k:k)) - ichar('0'), wp)
               gy = real(ichar(g(k + 1:k + 1)) - ichar('0'), wp) - 2.0_wp
               npt = npt + 1
               x(npt) = x0 + u*(c*gx - s*gy)
               y(npt) = y0 + u*(s*gx + c*gy)
               k = k + 2
            end do
         end if
         pen = pen + glyph_advance(text(i:i))
      end do
      first(nstroke + 1) = npt + 1
   end subroutine font_strokes

end module plot_font
