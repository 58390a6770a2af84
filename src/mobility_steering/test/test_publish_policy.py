import unittest

from mobility_steering.publish_policy import PublishPolicy


class PublishPolicyTest(unittest.TestCase):
    def test_quiet_before_anything_moves(self):
        policy = PublishPolicy(3)
        self.assertEqual([policy.tick(False) for _ in range(5)], [False] * 5)

    def test_every_tick_while_moving_then_three_zeros_then_quiet(self):
        policy = PublishPolicy(3)
        moving = [True] * 4 + [False] * 6
        self.assertEqual([policy.tick(m) for m in moving],
                         [True] * 4 + [True] * 3 + [False] * 3)

    def test_moving_again_rearms_the_tail(self):
        policy = PublishPolicy(2)
        ticks = [policy.tick(m) for m in (True, False, True, False, False, False)]
        self.assertEqual(ticks, [True, True, True, True, True, False])

    def test_restart_drops_a_pending_tail(self):
        policy = PublishPolicy(3)
        policy.tick(True)
        policy.restart()
        self.assertFalse(policy.tick(False))

    def test_rejects_no_zero_tail(self):
        with self.assertRaisesRegex(ValueError, 'got 0'):
            PublishPolicy(0)
