!> Timing of block generation and contact/domain detection for about 1k,
!> 10k and 100k blocks: a square cut by two orthogonal continuous joint sets.
!> Usage: geometry_bench [max_blocks]   (default 100000)
program geometry_bench
   use core_kinds, only: wp, ip, i8
   use core_error, only: error_t
   use model_geometry, only: geometry_t, geometry_init, geometry_live_blocks
   use geometry_cutting, only: cut_create_block, cut_set_round
   use geometry_joint_sets, only: joint_set
   use contact_detection, only: contact_rebuild
   use contact_domains, only: domain_rebuild
   implicit none
   integer(ip), parameter :: targets(3) = [1000, 10000, 100000]
   integer(ip) :: k, maxb
   character(len=32) :: arg
   maxb = 100000
   if (command_argument_count() > 0) then
      call get_command_argument(1, arg)
      read (arg, *) maxb
   end if
   write (*, '(a)') '  target  blocks  contacts  domains   build_s  contact_s   domain_s'
   do k = 1, size(targets)
      if (targets(k) <= maxb) call run(targets(k))
   end do

contains

   subroutine run(target)
      integer(ip), intent(in) :: target
      type(geometry_t) :: geo
      type(error_t), allocatable :: error
      real(wp), parameter :: side = 100.0_wp
      real(wp) :: s, t0, t1, t2, t3
      s = side/sqrt(real(target, wp))
      t0 = now()
      call geometry_init(geo)
      call cut_set_round(geo, 0.01_wp*s, error)
      call cut_create_block(geo, [0.0_wp, 0.0_wp, side, side], [0.0_wp, side, side, 0.0_wp], &
                            1, 1, error)
      call joint_set(geo, [0.0_wp, 0.0_wp], [10.0_wp*side, 0.0_wp], [0.0_wp, 0.0_wp], &
                     [s, 0.0_wp], error)
      call joint_set(geo, [90.0_wp, 0.0_wp], [10.0_wp*side, 0.0_wp], [0.0_wp, 0.0_wp], &
                     [s, 0.0_wp], error)
      t1 = now()
      call contact_rebuild(geo)
      t2 = now()
      call domain_rebuild(geo)
      t3 = now()
      write (*, '(i8,i8,i10,i9,3f11.3)') target, geometry_live_blocks(geo), geo%contacts%n, &
         geo%domains%n, t1 - t0, t2 - t1, t3 - t2
   end subroutine run

   real(wp) function now()
      integer(i8) :: count, rate
      call system_clock(count, rate)
      now = real(count, wp)/real(rate, wp)
   end function now

end program geometry_bench
