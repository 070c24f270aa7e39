"""Contact stage of the conrod pipeline ([D4]): contact intervals, Hertz stress,
friction work and wear on journal and shell, Greenwood–Tripp asperity contact, running-in.

Modules: :mod:`~conrod.contact.hertz`, :mod:`~conrod.contact.friction_work`,
:mod:`~conrod.contact.wear`, :mod:`~conrod.contact.asperity`, :mod:`~conrod.contact.mixed`,
:mod:`~conrod.contact.analysis` (``analyse_contact``, called by ``Simulation.run()``),
:mod:`~conrod.contact.running_in`. Kept import-free so that importing the package is cheap.
"""
