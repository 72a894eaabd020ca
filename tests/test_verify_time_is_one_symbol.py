"""The time t a text writes is the reader's own t, however much the process has read before."""
from sympy.core.cache import clear_cache

from derive.lecture import notes_check as nc


def test_t_set_to_a_value_is_a_setting_after_sympys_cache_is_emptied():
    # a text read after others in one process meets a SymPy cache that has dropped the Symbol t:
    # the t it writes must still be the t the checker knows (fails where it is compared by identity)
    clear_cache()
    claims = nc.check_text("The top starts at rest.\n\n$$\nt = 0\n$$\n", "z-x-z")
    assert [(c.kind, c.verdict) for c in claims] == [("setting", "unchecked")]
    assert claims[0].why.startswith("sets t = 0")
