"""The benchmark: a client of the package, never imported by it (only ``derive bench`` calls it).

Takes: the reference scene (the shipped example ``reference_top``, :mod:`~derive.bench.reference`)
and the example scenes. Gives: ``derive bench``'s report (:mod:`~derive.bench.suite`): the
kernel speed and work–precision races against SciPy, CasADi, PyDy, heyoka and numbalsoda at equal error
(:mod:`~derive.bench.runner`, :mod:`~derive.bench.contenders`, :mod:`~derive.bench.peers`, whose baselines ship in
``derive/bench/baselines``), the targets (:mod:`~derive.bench.targets`; the notes reader's speed on
the corpus in :mod:`~derive.bench.verify_speed`), the sweep's
throughput (:mod:`~derive.bench.throughput`), the splittings (:mod:`~derive.bench.splitting`)
and the write-up (:mod:`~derive.bench.report`).

May import: anything in :mod:`derive`. Nothing but :mod:`derive.cli` imports it.
"""
