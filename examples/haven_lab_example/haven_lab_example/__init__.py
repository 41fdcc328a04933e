"""A lab's own HAVEN plugins (an example): `people.Hurried`, `near.seconds_near`, `trust.TRUST`."""
