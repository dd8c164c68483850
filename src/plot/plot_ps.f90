!> PostScript device: the scene as a one-page Encapsulated PostScript file
!> (valid as .ps and .eps), written directly. Lines keep their widths, text
!> uses the Helvetica font every PostScript interpreter has; one page unit
!> is 0.6 point (the default 1200 x 840 page is 10 x 7 inches).
module plot_ps
   use core_kinds, only: wp
   use core_error, only: error_t, set_error
   use core_version, only: udec_name, udec_version
   use plot_scene, only: plot_scene_t, item_polyline, item_polygon, item_fill, item_text
   use plot_device, only: plot_device_t
   implicit none
   private
   public :: ps_device_t, ps_points_per_unit

   real(wp), parameter :: ps_points_per_unit = 0.6_wp
   !> Helvetica's cap height is 0.718 of its font size.
   real(wp), parameter :: cap_height = 0.718_wp

   type, extends(plot_device_t) :: ps_device_t
   contains
      procedure :: write => ps_write
   end type ps_device_t

contains

   subroutine ps_write(this, scene, path, error)
      class(ps_device_t), intent(in) :: this
      type(plot_scene_t), intent(in) :: scene
      character(len=*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      integer :: u, ios, k, j
      logical :: clipping
      character(len=64) :: buf
      open (newunit=u, file=path, status='replace', action='write', form='formatted', &
            iostat=ios)
      if (ios /= 0) then
         call set_error(error, "COPY: cannot write the PostScript file '"//path//"'")
         return
      end if
      write (u, '(a)') '%!PS-Adobe-3.0 EPSF-3.0'
      write (buf, '(a,i0,1x,i0)') '%%BoundingBox: 0 0 ', &
         ceiling(scene%page_w*ps_points_per_unit), ceiling(scene%page_h*ps_points_per_unit)
      write (u, '(a)') trim(buf)
      write (u, '(a)') '%%Title: ('//ps_string(scene%heading)//')'
      write (u, '(a)') '%%Creator: '//udec_name//' '//udec_version//' ('//this%name()//' device)'
      write (u, '(a)') '%%Pages: 1'
      write (u, '(a)') '%%DocumentNeededResources: font Helvetica'
      write (u, '(a)') '%%EndComments'
      write (u, '(a)') '%%BeginProlog'
      write (u, '(a)') '/udecdict 16 dict def udecdict begin'
      write (u, '(a)') '/M {moveto} bind def /L {lineto} bind def'
      write (u, '(a)') '/C {setrgbcolor} bind def /W {setlinewidth} bind def'
      write (u, '(a)') '/S {stroke} bind def /P {closepath stroke} bind def'
      write (u, '(a)') '/F {closepath fill} bind def'
      write (u, '(a)') '% string x y capheight align angle T: text, align 0 left .5 centre 1 right'
      write (u, '(a)') '/T {gsave /ang exch def /al exch def /sz exch def M ang rotate'
      write (u, '(a)') ' /Helvetica findfont sz scalefont setfont'
      write (u, '(a)') ' dup stringwidth pop al mul neg 0 rmoveto show grestore} bind def'
      write (u, '(a)') 'end'
      write (u, '(a)') '%%EndProlog'
      write (u, '(a)') '%%Page: 1 1'
      write (u, '(a)') 'udecdict begin gsave'
      write (buf, '(2(f0.4,1x),a)') ps_points_per_unit, ps_points_per_unit, 'scale'
      write (u, '(a)') trim(buf)
      write (u, '(a)') '1 setlinejoin 1 setlinecap'
      write (u, '(a)') '1 1 1 C 0 0 '//num(scene%page_w)//' '//num(scene%page_h)//' rectfill'
      clipping = .false.
      do k = 1, scene%nitem
         associate (it => scene%items(k))
            if (it%clip .neqv. clipping) then
               if (clipping) then
                  write (u, '(a)') 'grestore'
               else
                  write (u, '(a)') 'gsave '//num(scene%vx0)//' '//num(scene%vy0)//' '// &
                     num(scene%vx1 - scene%vx0)//' '//num(scene%vy1 - scene%vy0)//' rectclip'
               end if
               clipping = it%clip
            end if
            write (u, '(a)') num3(it%colour(1))//' '//num3(it%colour(2))//' '// &
               num3(it%colour(3))//' C'
            select case (it%kind)
            case (item_text)
               write (u, '(a)') '('//ps_string(it%text)//') '//num(scene%x(it%first))//' '// &
                  num(scene%y(it%first))//' '//num(it%size/cap_height)//' '// &
                  num3(0.5_wp*real(it%align, wp))//' '//num(it%angle)//' T'
            case default
               if (it%kind /= item_fill) write (u, '(a)') num(it%width)//' W'
               write (u, '(a)') num(scene%x(it%first))//' '//num(scene%y(it%first))//' M'
               do j = it%first + 1, it%first + it%count - 1
                  write (u, '(a)') num(scene%x(j))//' '//num(scene%y(j))//' L'
               end do
               select case (it%kind)
               case (item_polyline)
                  write (u, '(a)') 'S'
               case (item_polygon)
                  write (u, '(a)') 'P'
               case (item_fill)
                  write (u, '(a)') 'F'
               end select
            end select
         end associate
      end do
      if (clipping) write (u, '(a)') 'grestore'
      write (u, '(a)') 'grestore end'
      write (u, '(a)') 'showpage'
      write (u, '(a)') '%%EOF'
      close (u, iostat=ios)
      if (ios /= 0) call set_error(error, "COPY: error writing the PostScript file '"//path//"'")
   end subroutine ps_write

   !> A page coordinate with two decimals ("12.25", "-0.5").
   function num(v) result(text)
      real(wp), intent(in) :: v
      character(len=:), allocatable :: text
      character(len=32) :: buf
      write (buf, '(f0.2)') v
      text = trim(adjustl(buf))
      if (text(1:1) == '.') text = '0'//text
      if (text(1:2) == '-.') text = '-0'//text(2:)
   end function num

   !> A colour component or fraction with three decimals.
   function num3(v) result(text)
      real(wp), intent(in) :: v
      character(len=:), allocatable :: text
      character(len=32) :: buf
      write (buf, '(f5.3)') max(0.0_wp, min(1.0_wp, v))
      text = trim(adjustl(buf))
   end function num3

   !> Text for a PostScript string literal: \, ( and ) escaped, anything
   !> outside printable ASCII replaced by '?'.
   function ps_string(text) result(s)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: s
      integer :: i
      s = ''
      do i = 1, len(text)
         select case (text(i:i))
         case ('\', '(', ')')
            s = s//'\'//text(i:i)
         case default
            if (iachar(text(i:i)) < 32 .or. iachar(text(i:i)) > 126) then
               s = s//'?'
            else
               s = s//text(i:i)
            end if
         end select
      end do
   end function ps_string

end module plot_ps
