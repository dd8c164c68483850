file(REMOVE_RECURSE
  "libudec_contact.a"
)
