"""Parametric parts built with CadQuery. The only package that imports cadquery."""
