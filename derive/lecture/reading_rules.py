"""The reading rules a notes checker is made of: one mixin per family of shapes a text writes.

`derive.lecture.notes_check.Checker` walks a text and keeps its context; each class below reads
one family of displays (a text's own names, its matrices, perturbations, quaternions, sums of
unlike quantities, …) and is documented in its own module. Their order is the order Python
looks a method up in (a rule earlier in the list wins a name two of them define), so a new rule
goes at the end unless it must override one.

Takes and gives nothing of its own. May import: the rule modules of :mod:`derive.lecture`.
"""
from __future__ import annotations

from derive.lecture.algebra_claims import AlgebraStatements
from derive.lecture.axis_angle_turns import AxisAngleTurns
from derive.lecture.axis_products import AxisProducts
from derive.lecture.basis_vectors import BasisVectors
from derive.lecture.body_links import BodyLinks
from derive.lecture.hat_basis import HatBasis
from derive.lecture.chain_end_names import ChainEndNames
from derive.lecture.chain_links import ChainLinks
from derive.lecture.conditions import Conditions
from derive.lecture.constant_cases import ConstantCases
from derive.lecture.constants_collapsed import ConstantsCollapsed
from derive.lecture.context import Reading
from derive.lecture.coordinate_statements import CoordinateStatements
from derive.lecture.determinant_steps import DeterminantSteps
from derive.lecture.eom_case_value import CaseValue
from derive.lecture.eom_restated_member import RestatedMember
from derive.lecture.euler_in_angles import EulerInAngles
from derive.lecture.elliptic_solution import EllipticSolution
from derive.lecture.euler_poisson import EulerPoisson
from derive.lecture.exponent_relations import ExponentRelations
from derive.lecture.fast_top import FastTop
from derive.lecture.nutation_rate import NutationRate
from derive.lecture.frame_displays import FrameDisplays
from derive.lecture.head_shapes import HeadShapes
from derive.lecture.implications import Implications
from derive.lecture.free_indices import FreeIndices
from derive.lecture.free_integrals import FreeIntegrals
from derive.lecture.index_euler import IndexEuler
from derive.lecture.index_sums import IndexSums
from derive.lecture.inferred_convention import ConventionProbe
from derive.lecture.integral_claims import IntegralClaims
from derive.lecture.judging import Judging
from derive.lecture.letter_digits import LetterDigits
from derive.lecture.lost_backslash import LostBackslash
from derive.lecture.moments_small import SmallMoments
from derive.lecture.named_vector_claims import NamedVectors
from derive.lecture.nested_spins import NestedSpins
from derive.lecture.motion import Motion
from derive.lecture.on_the_motion import OnTheMotion
from derive.lecture.operator_statements import OperatorStatements
from derive.lecture.own_sign import OwnSign
from derive.lecture.own_turns import OwnTurns
from derive.lecture.perturbations import Perturbations
from derive.lecture.primed_axes import PrimedAxes
from derive.lecture.problem_sections import ProblemSections
from derive.lecture.quaternions import Quaternions
from derive.lecture.rotation_products import RotationProducts
from derive.lecture.scalar_vector_sums import ScalarVectorSums
from derive.lecture.rereading import Rereading
from derive.lecture.restated import Restated
from derive.lecture.section_convention import SectionConvention
from derive.lecture.shape_moments import ShapeMoments
from derive.lecture.stated_theorems import StatedTheorems
from derive.lecture.text_matrices import TextMatrices
from derive.lecture.text_motion import TextMotion
from derive.lecture.textnames import TextNames
from derive.lecture.turn_rates import TurnRates
from derive.lecture.two_cases import TwoCases
from derive.lecture.unlike_terms import UnlikeTerms
from derive.lecture.unspun_frame import UnspunFrame
from derive.lecture.untied_links import UntiedLinks
from derive.lecture.untied_partials import UntiedPartials
from derive.lecture.vector_claims import VectorStatements
from derive.lecture.vector_size import VectorSize
from derive.lecture.written_out import WrittenOut


class ReadingRules(IntegralClaims, Perturbations, ConventionProbe, SectionConvention, ConstantCases,
                   Conditions, EulerInAngles, EulerPoisson, FastTop, NutationRate, FreeIntegrals, WrittenOut, TextNames,
                   TextMatrices, TextMotion, Rereading, CaseValue, RestatedMember, Motion, Reading, VectorStatements, OnTheMotion,
                   AlgebraStatements, SmallMoments, Judging, OperatorStatements, CoordinateStatements,
                   ChainLinks, AxisProducts, Restated, ChainEndNames, PrimedAxes, TurnRates, StatedTheorems,
                   FrameDisplays, OwnSign, UnlikeTerms, BasisVectors, TwoCases, Quaternions,
                   EllipticSolution, Implications, DeterminantSteps, ShapeMoments, RotationProducts,
                   NestedSpins, AxisAngleTurns, FreeIndices, NamedVectors, HatBasis, HeadShapes,
                   LostBackslash, LetterDigits, ScalarVectorSums, BodyLinks, IndexSums,
                   UntiedPartials, VectorSize, ProblemSections, UntiedLinks, IndexEuler, ConstantsCollapsed,
                   OwnTurns, ExponentRelations, UnspunFrame):
    """Every reading rule, in method-lookup order (see the module docstring)."""
