"""The elastic big end: finite-element housing, compliance, inertia deformation, stresses.

Start with :class:`conrod.elastic.housing.Housing` (``Housing.from_case(case)``); the
method and its checks are described in docs/elastic.md.
"""
