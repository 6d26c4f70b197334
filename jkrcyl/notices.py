"""Warnings jkrcyl gives where it answers but the answer has a stated limit."""


class ValidityWarning(UserWarning):
    """An input outside the theory's assumptions (e.g. a clearance Delta not small against R): the answer is
    computed, but its error is of the order the warning states."""


class BranchLimitWarning(UserWarning):
    """A search reached the end of a branch's table (the solver traced it only so far): states beyond it were not
    searched, and the warning says where the table ends."""
