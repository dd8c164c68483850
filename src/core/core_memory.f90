!> Memory policy of the process (core_memory.c): large arrays are returned to
!> the system when freed (issue 23, peak memory of large models).
module core_memory
   implicit none
   private
   public :: memory_policy

   interface
      subroutine c_memory_policy() bind(c, name='udec_memory_policy')
      end subroutine c_memory_policy
   end interface

contains

   !> Set once per process (later calls do nothing).
   subroutine memory_policy()
      call c_memory_policy()
   end subroutine memory_policy

end module core_memory
