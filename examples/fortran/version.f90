!> Prints the version of the linked udmap library.
program version
  use udmap, only: udmap_version
  implicit none
  print '(a)', udmap_version()
end program version
