file(REMOVE_RECURSE
  "libudec_testing_session.a"
)
