"""The model core: the normalised problem (:mod:`.problem`), the single-patch solvers (:mod:`.single_patch`:
the only place that knows whether a pair has a closed form), two patches and full contact (:mod:`.two_patch`,
:mod:`.full_contact`) and stability (:mod:`.stability`)."""
