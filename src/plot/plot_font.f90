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

contains

   !> Strokes of character `ch` ('?' for characters the table lacks).
   pure function font_glyph(ch) result(g)
      character, intent(in) :: ch
      character(len=:), allocatable :: g
      select case (ch)
      case ('A'); g = '0206284642 0545'
      case ('B'); g = '02083847463505 3544433202'
      case ('C'); g = '4738180703123243'
      case ('D'); g = '02083847433202'
      case ('E'); g = '48080242 0535'
      case ('F'); g = '480802 0535'
      case ('G'); g = '47381807031232434525'
      case ('H'); g = '0208 4248 0545'
      case ('I'); g = '1232 2228 1838'
      case ('J'); g = '4843321203'
      case ('K'); g = '0208 4804 1542'
      case ('L'); g = '080242'
      case ('M'); g = '0208254842'
      case ('N'); g = '02084248'
      case ('O'); g = '120307183847433212'
      case ('P'); g = '02083847463505'
      case ('Q'); g = '120307183847433212 2442'
      case ('R'); g = '02083847463505 2542'
      case ('S'); g = '473818070615354443321203'
      case ('T'); g = '0848 2822'
      case ('U'); g = '080312324348'
      case ('V'); g = '082248'
      case ('W'); g = '0812253248'
      case ('X'); g = '0842 0248'
      case ('Y'); g = '082548 2522'
      case ('Z'); g = '08480242'
      case ('a'); g = '16364542 441403123243'
      case ('b'); g = '08023243453606'
      case ('c'); g = '461605031242'
      case ('d'); g = '48421203051646'
      case ('e'); g = '044445361605031242'
      case ('f'); g = '48382722 1636'
      case ('g'); g = '43321203051646413000'
      case ('h'); g = '0802 0516364542'
      case ('i'); g = '0602 0807'
      case ('j'); g = '161100 1817'
      case ('k'); g = '0802 3603 1432'
      case ('l'); g = '080312'
      case ('m'); g = '0206 05162522 25364542'
      case ('n'); g = '0206 0516364542'
      case ('o'); g = '120305163645433212'
      case ('p'); g = '00063645433202'
      case ('q'); g = '40461605031242'
      case ('r'); g = '0206 042646'
      case ('s'); g = '4616051434433202'
      case ('t'); g = '18132232 0636'
      case ('u'); g = '0603123243 4642'
      case ('v'); g = '062246'
      case ('w'); g = '0612243246'
      case ('x'); g = '0642 0246'
      case ('y'); g = '0622 461000'
      case ('z'); g = '06460242'
      case ('0'); g = '120307183847433212 1337'
      case ('1'); g = '172822 1232'
      case ('2'); g = '07183847460242'
      case ('3'); g = '07183847463515 354443321203'
      case ('4'); g = '32380444'
      case ('5'); g = '4808053544433202'
      case ('6'); g = '4738180703123243443505'
      case ('7'); g = '084812'
      case ('8'); g = '15060718384746351504031232434435'
      case ('9'); g = '0312324347381807061545'
      case ('.'); g = '0212'
      case (','); g = '131201'
      case (':'); g = '0212 0616'
      case (';'); g = '1616 131201'
      case ('-'); g = '0535'
      case ('+'); g = '0545 2327'
      case ('='); g = '0444 0646'
      case ('('); g = '29070321'
      case (')'); g = '09272301'
      case ('['); g = '29090121'
      case (']'); g = '09292101'
      case ('/'); g = '0248'
      case ('\'); g = '0842'
      case ('|'); g = '0109'
      case ('*'); g = '2327 0446 0644'
      case ('%'); g = '0248 0818170708 3343423233'
      case ('_'); g = '0141'
      case ('!'); g = '0804 0212'
      case ('?'); g = '07183847462524 2322'
      case (''''); g = '0806'
      case ('"'); g = '0806 2826'
      case ('`'); g = '0817'
      case ('#'); g = '1218 3238 0444 0646'
      case ('<'); g = '460442'
      case ('>'); g = '064402'
      case ('^'); g = '062846'
      case ('~'); g = '05163545'
      case ('$'); g = '473818070615354443321203 2129'
      case ('&'); g = '42061718372604031222 3443'
      case ('@'); g = '3424133536 364443321203071838474604'
      case ('{'); g = '2938363505343321 0515'
      case ('}'); g = '0918161525141301 2535'
      case default; g = '07183847462524 2322'
      end select
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
