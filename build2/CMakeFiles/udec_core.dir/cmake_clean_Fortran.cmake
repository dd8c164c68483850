# Remove fortran modules provided by this target.
FILE(REMOVE
  "mod/core/core_arrays.mod"
  "mod/core/CORE_ARRAYS.mod"
  "CMakeFiles/udec_core.dir/core_arrays.mod.stamp"

  "mod/core/core_constants.mod"
  "mod/core/CORE_CONSTANTS.mod"
  "CMakeFiles/udec_core.dir/core_constants.mod.stamp"

  "mod/core/core_error.mod"
  "mod/core/CORE_ERROR.mod"
  "CMakeFiles/udec_core.dir/core_error.mod.stamp"

  "mod/core/core_files.mod"
  "mod/core/CORE_FILES.mod"
  "CMakeFiles/udec_core.dir/core_files.mod.stamp"

  "mod/core/core_forces.mod"
  "mod/core/CORE_FORCES.mod"
  "CMakeFiles/udec_core.dir/core_forces.mod.stamp"

  "mod/core/core_interrupt.mod"
  "mod/core/CORE_INTERRUPT.mod"
  "CMakeFiles/udec_core.dir/core_interrupt.mod.stamp"

  "mod/core/core_kinds.mod"
  "mod/core/CORE_KINDS.mod"
  "CMakeFiles/udec_core.dir/core_kinds.mod.stamp"

  "mod/core/core_limits.mod"
  "mod/core/CORE_LIMITS.mod"
  "CMakeFiles/udec_core.dir/core_limits.mod.stamp"

  "mod/core/core_lineedit.mod"
  "mod/core/CORE_LINEEDIT.mod"
  "CMakeFiles/udec_core.dir/core_lineedit.mod.stamp"

  "mod/core/core_output.mod"
  "mod/core/CORE_OUTPUT.mod"
  "CMakeFiles/udec_core.dir/core_output.mod.stamp"

  "mod/core/core_progress.mod"
  "mod/core/CORE_PROGRESS.mod"
  "CMakeFiles/udec_core.dir/core_progress.mod.stamp"

  "mod/core/core_range.mod"
  "mod/core/CORE_RANGE.mod"
  "CMakeFiles/udec_core.dir/core_range.mod.stamp"

  "mod/core/core_sort.mod"
  "mod/core/CORE_SORT.mod"
  "CMakeFiles/udec_core.dir/core_sort.mod.stamp"

  "mod/core/core_strings.mod"
  "mod/core/CORE_STRINGS.mod"
  "CMakeFiles/udec_core.dir/core_strings.mod.stamp"

  "mod/core/core_version.mod"
  "mod/core/CORE_VERSION.mod"
  "CMakeFiles/udec_core.dir/core_version.mod.stamp"
  )
