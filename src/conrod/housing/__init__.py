"""The elastic big end as a structure: built-in rod geometry and mesher, finite elements
(scikit-fem), imported meshes and compliance matrices, inertia deformation, rigid-body
correction, transfer to the film nodes and rod stresses. It knows no film: the film–bore
coupling is :mod:`conrod.ehd`.

Start with :class:`conrod.housing.housing.Housing` (``Housing.from_case(case)``); the method
and its checks are described in docs/elastic.md.
"""
