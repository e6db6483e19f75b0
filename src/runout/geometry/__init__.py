"""Geometry and physics of one bearing: bearing and material descriptions, imperfections
(harmonics, profiles), kinematics, Hertz contact (elliptic integrals), static loading and the
operating contact angle, frequency attribution, the spindle layout. Imports only base.
"""
